#include "strahler/vector_tile/tile_geometry.h"

#include "strahler/geometry/polyline_simplify.h"

#include <cmath>

namespace strahler::vector_tile {
namespace {

using geometry::Vec2;

/// The parameters [t0, t1] ⊆ [0, 1] of segment a→b inside `box`; false when it misses it.
bool clipSegment(Vec2 a, Vec2 b, const ClipBox& box, double& t0, double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  const double d[2] = {b.x - a.x, b.y - a.y};
  const double p[2] = {a.x, a.y};
  for (int axis = 0; axis < 2; ++axis) {
    const double lo = box.lo - p[axis], hi = box.hi - p[axis];
    if (d[axis] == 0.0) {
      if (lo > 0.0 || hi < 0.0)
        return false;
      continue;
    }
    double enter = lo / d[axis], leave = hi / d[axis];
    if (enter > leave)
      std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
    if (t0 > t1)
      return false;
  }
  return true;
}

Vec2 pointAt(Vec2 a, Vec2 b, double t) {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
}

/// One Sutherland–Hodgman pass: keeps the side of `ring` where inside(p) holds.
template <class Inside, class Cross>
std::vector<Vec2> clipAgainst(const std::vector<Vec2>& ring, Inside inside, Cross cross) {
  std::vector<Vec2> out;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[(i + n - 1) % n], b = ring[i];
    const bool ina = inside(a), inb = inside(b);
    if (inb) {
      if (!ina)
        out.push_back(cross(a, b));
      out.push_back(b);
    } else if (ina) {
      out.push_back(cross(a, b));
    }
  }
  return out;
}

} // namespace

std::vector<std::vector<Vec2>> clipLine(std::span<const Vec2> line, const ClipBox& box) {
  std::vector<std::vector<Vec2>> pieces;
  bool open = false; // the last piece ends where the next segment starts
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    double t0 = 0.0, t1 = 0.0;
    if (!clipSegment(line[i], line[i + 1], box, t0, t1)) {
      open = false;
      continue;
    }
    if (!open || t0 > 0.0) {
      pieces.emplace_back();
      pieces.back().push_back(pointAt(line[i], line[i + 1], t0));
    }
    pieces.back().push_back(t1 < 1.0 ? pointAt(line[i], line[i + 1], t1) : line[i + 1]);
    open = t1 >= 1.0;
  }
  if (line.size() == 1 && box.contains(line[0]))
    pieces.push_back({line[0]});
  return pieces;
}

std::vector<Vec2> clipRing(std::span<const Vec2> ring, const ClipBox& box) {
  std::vector<Vec2> out(ring.begin(), ring.end());
  const double lo = box.lo, hi = box.hi;
  const auto atX = [](double x) {
    return [x](Vec2 a, Vec2 b) { return Vec2{x, a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x)}; };
  };
  const auto atY = [](double y) {
    return [y](Vec2 a, Vec2 b) { return Vec2{a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y), y}; };
  };
  out = clipAgainst(
      out, [lo](Vec2 p) { return p.x >= lo; }, atX(lo));
  out = clipAgainst(
      out, [hi](Vec2 p) { return p.x <= hi; }, atX(hi));
  out = clipAgainst(
      out, [lo](Vec2 p) { return p.y >= lo; }, atY(lo));
  out = clipAgainst(
      out, [hi](Vec2 p) { return p.y <= hi; }, atY(hi));
  if (out.size() < 3)
    out.clear();
  return out;
}

double ringArea2(std::span<const Vec2> ring) noexcept {
  double sum = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % n];
    sum += a.x * b.y - b.x * a.y;
  }
  return sum;
}

std::vector<Point> toTilePoints(std::span<const Vec2> line, double tolerance, bool ring) {
  std::vector<Vec2> closed;
  if (ring && !line.empty()) {
    closed.assign(line.begin(), line.end());
    closed.push_back(line.front());
    line = closed;
  }
  std::vector<Point> out;
  for (const std::size_t k : geometry::simplifyPolyline(line, tolerance)) {
    const Point p{static_cast<std::int32_t>(std::lround(line[k].x)),
                  static_cast<std::int32_t>(std::lround(line[k].y))};
    if (out.empty() || !(out.back() == p))
      out.push_back(p);
  }
  while (ring && out.size() > 1 && out.back() == out.front())
    out.pop_back();
  return out;
}

} // namespace strahler::vector_tile
