#include "strahler/geometry/polygon.h"

#include <algorithm>
#include <cmath>

namespace strahler::geometry {

double signedArea(const Ring& ring) noexcept {
  const std::size_t n = ring.size();
  if (n < 3)
    return 0.0;
  // Shoelace relative to the first vertex, to keep precision in large frames.
  const Vec2 o = ring[0];
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i)
    twice += cross(ring[i] - o, ring[i + 1] - o);
  return 0.5 * twice;
}

double area(const Polygon& polygon) noexcept {
  double a = std::abs(signedArea(polygon.outer));
  for (const Ring& hole : polygon.holes)
    a -= std::abs(signedArea(hole));
  return std::max(0.0, a);
}

double area(const MultiPolygon& polygons) noexcept {
  double a = 0.0;
  for (const Polygon& p : polygons)
    a += area(p);
  return a;
}

Aabb bounds(const Ring& ring) noexcept {
  Aabb box;
  for (Vec2 p : ring)
    box.add(p);
  return box;
}

Aabb bounds(const MultiPolygon& polygons) noexcept {
  Aabb box;
  for (const Polygon& p : polygons)
    box.add(bounds(p.outer));
  return box;
}

bool contains(const Ring& ring, Vec2 p) noexcept {
  bool inside = false;
  const std::size_t n = ring.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 a = ring[i];
    const Vec2 b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
      if (p.x < x)
        inside = !inside;
    }
  }
  return inside;
}

bool contains(const Polygon& polygon, Vec2 p) noexcept {
  if (!contains(polygon.outer, p))
    return false;
  for (const Ring& hole : polygon.holes)
    if (contains(hole, p))
      return false;
  return true;
}

double perimeter(const MultiPolygon& polygons) noexcept {
  double total = 0.0;
  auto ringLength = [](const Ring& r) {
    double l = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i)
      l += distance(r[i], r[(i + 1) % r.size()]);
    return l;
  };
  for (const Polygon& p : polygons) {
    total += ringLength(p.outer);
    for (const Ring& h : p.holes)
      total += ringLength(h);
  }
  return total;
}

void orient(Polygon& polygon) noexcept {
  if (signedArea(polygon.outer) < 0)
    std::reverse(polygon.outer.begin(), polygon.outer.end());
  for (Ring& h : polygon.holes)
    if (signedArea(h) > 0)
      std::reverse(h.begin(), h.end());
}

std::size_t vertexCount(const MultiPolygon& polygons) noexcept {
  std::size_t n = 0;
  for (const Polygon& p : polygons) {
    n += p.outer.size();
    for (const Ring& h : p.holes)
      n += h.size();
  }
  return n;
}

Vec2 centroid(const MultiPolygon& polygons) noexcept {
  double totalArea = 0.0;
  Vec2 sum{};
  auto accumulate = [&](const Ring& r, double sign) {
    if (r.size() < 3)
      return;
    const Vec2 o = r[0];
    for (std::size_t i = 1; i + 1 < r.size(); ++i) {
      const double a = 0.5 * cross(r[i] - o, r[i + 1] - o) * sign;
      sum += (o + r[i] + r[i + 1]) * (a / 3.0);
      totalArea += a;
    }
  };
  for (const Polygon& p : polygons) {
    const double outerSign = signedArea(p.outer) >= 0 ? 1.0 : -1.0;
    accumulate(p.outer, outerSign);
    for (const Ring& h : p.holes)
      accumulate(h, signedArea(h) >= 0 ? -1.0 : 1.0);
  }
  if (totalArea == 0.0)
    return bounds(polygons).center();
  return sum / totalArea;
}

Ring clipToConvex(const Ring& ring, const Ring& window) {
  Ring output = ring;
  Ring input;
  const std::size_t m = window.size();
  for (std::size_t e = 0; e < m && !output.empty(); ++e) {
    const Vec2 a = window[e];
    const Vec2 b = window[(e + 1) % m];
    const Vec2 edge = b - a;
    input.swap(output);
    output.clear();
    const std::size_t n = input.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 cur = input[i];
      const Vec2 prev = input[(i + n - 1) % n];
      const double dc = cross(edge, cur - a);
      const double dp = cross(edge, prev - a);
      if (dc >= 0) {
        if (dp < 0)
          output.push_back(lerp(prev, cur, dp / (dp - dc)));
        output.push_back(cur);
      } else if (dp >= 0) {
        output.push_back(lerp(prev, cur, dp / (dp - dc)));
      }
    }
  }
  if (output.size() < 3)
    output.clear();
  return output;
}

} // namespace strahler::geometry
