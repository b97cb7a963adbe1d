#include "ring_validation.h"

#include "strahler/geometry/distance.h"
#include "strahler/geometry/polygon_index.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>
#include <utility>

namespace strahler::input::detail {
namespace {

using base::ErrorCode;
using base::makeError;
using geometry::Aabb;
using geometry::Vec2;

/// One boundary segment, from vertex `index` to the next of ring `ring` of `polygon`.
struct Segment {
  Vec2 a;
  Vec2 b;
  Aabb box;
  std::uint32_t polygon = 0;
  std::uint32_t ring = 0;
  std::uint32_t index = 0;
  std::uint32_t ringSize = 0;
};

bool boxContains(const Aabb& outer, const Aabb& inner) noexcept {
  return outer.contains(inner.min) && outer.contains(inner.max);
}

const ParsedRing& ringOf(const std::vector<ParsedPolygon>& polygons, const Segment& s) {
  return polygons[s.polygon].rings[s.ring];
}

/// "segment 3 (positions 3-4)", in the numbering of the input file.
std::string describeSegment(const std::vector<ParsedPolygon>& polygons, const Segment& s) {
  const ParsedRing& ring = ringOf(polygons, s);
  const std::uint32_t from = ring.positions[s.index];
  const std::uint32_t to =
      s.index + 1 < ring.positions.size() ? ring.positions[s.index + 1] : ring.closingPosition;
  return "segment " + std::to_string(from) + " (positions " + std::to_string(from) + "-" +
         std::to_string(to) + ")";
}

/// A point common to two segments known to meet: where their lines cross, or for collinear
/// segments an endpoint of one that lies on the other.
Vec2 meetingPoint(const Segment& s, const Segment& t) noexcept {
  const Vec2 u = s.b - s.a, v = t.b - t.a;
  const double d = geometry::cross(u, v);
  if (d != 0.0)
    return s.a + u * (geometry::cross(t.a - s.a, v) / d);
  for (const Vec2 p : {t.a, t.b})
    if (s.box.contains(p))
      return p;
  return s.a;
}

/// "(-16.49001, 63.90021)": a place in degrees, to about a metre.
std::string formatPlace(Vec2 p) {
  std::array<char, 64> text{};
  std::snprintf(text.data(), text.size(), "(%.5f, %.5f)", p.x, p.y);
  return text.data();
}

base::Error crossingError(const std::vector<ParsedPolygon>& polygons, const Segment& s,
                          const Segment& t) {
  const std::string& label = polygons[s.polygon].label;
  const std::string first = describeSegment(polygons, s);
  const std::string second =
      describeSegment(polygons, t) + " at " + formatPlace(meetingPoint(s, t));
  if (s.polygon == t.polygon && s.ring == t.ring)
    return makeError(ErrorCode::kInvalidInput,
                     "coastline: " + label + ", ring " + std::to_string(s.ring) +
                         ": ring intersects itself: " + first + " touches or crosses " + second);
  const std::string where = first + " of ring " + std::to_string(s.ring) + " meets " + second +
                            " of ring " + std::to_string(t.ring);
  if (s.polygon == t.polygon)
    return makeError(ErrorCode::kInvalidInput,
                     "coastline: " + label + ": rings " + std::to_string(s.ring) + " and " +
                         std::to_string(t.ring) + " touch or cross: " + where +
                         (s.ring == 0 ? " (a hole must lie strictly inside its outer ring)"
                                      : " (holes must not touch each other)"));
  return makeError(ErrorCode::kInvalidInput, "coastline: " + label + " and " +
                                                 polygons[t.polygon].label + " overlap: " + where +
                                                 " (polygons must not touch or overlap)");
}

std::vector<Segment> collectSegments(const std::vector<ParsedPolygon>& polygons, Aabb& all,
                                     double& totalLength) {
  std::vector<Segment> segments;
  totalLength = 0.0;
  for (std::uint32_t p = 0; p < polygons.size(); ++p)
    for (std::uint32_t r = 0; r < polygons[p].rings.size(); ++r) {
      const geometry::Ring& v = polygons[p].rings[r].vertices;
      const auto m = static_cast<std::uint32_t>(v.size());
      for (std::uint32_t i = 0; i < m; ++i) {
        Segment s{v[i], v[(i + 1) % m], {}, p, r, i, m};
        s.box.add(s.a);
        s.box.add(s.b);
        all.add(s.box);
        totalLength += geometry::distance(s.a, s.b);
        segments.push_back(s);
      }
    }
  return segments;
}

/// Sparse uniform grid: (cell key, segment) pairs sorted by key. The cell side starts at
/// twice the mean segment length and doubles until the entries stay within 4 per segment.
std::vector<std::pair<std::uint64_t, std::uint32_t>>
buildCells(const std::vector<Segment>& segments, const Aabb& all, double totalLength) {
  const double n = static_cast<double>(segments.size());
  const Vec2 size = all.size();
  double cell = std::max({2.0 * totalLength / n, std::max(size.x, size.y) / 1048576.0, 1e-12});
  const std::uint64_t cap = 4u * static_cast<std::uint64_t>(segments.size()) + 4096u;
  auto cellOf = [&](double v, double origin) {
    return static_cast<std::uint64_t>(std::max(0.0, std::floor((v - origin) / cell)));
  };
  for (;;) {
    std::uint64_t entries = 0;
    for (const Segment& s : segments) {
      entries += (cellOf(s.box.max.x, all.min.x) - cellOf(s.box.min.x, all.min.x) + 1) *
                 (cellOf(s.box.max.y, all.min.y) - cellOf(s.box.min.y, all.min.y) + 1);
      if (entries > cap)
        break;
    }
    if (entries <= cap)
      break;
    cell *= 2.0;
  }
  std::vector<std::pair<std::uint64_t, std::uint32_t>> cells;
  for (std::uint32_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    for (std::uint64_t y = cellOf(s.box.min.y, all.min.y); y <= cellOf(s.box.max.y, all.min.y); ++y)
      for (std::uint64_t x = cellOf(s.box.min.x, all.min.x); x <= cellOf(s.box.max.x, all.min.x);
           ++x)
        cells.emplace_back((y << 32) | x, i);
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

bool adjacent(const Segment& s, const Segment& t) noexcept {
  if (s.polygon != t.polygon || s.ring != t.ring)
    return false;
  const std::uint32_t d = s.index > t.index ? s.index - t.index : t.index - s.index;
  return d == 1 || d + 1 == s.ringSize;
}

base::Status checkCrossings(const std::vector<ParsedPolygon>& polygons,
                            std::uint64_t maxPairTests) {
  Aabb all;
  double totalLength = 0.0;
  const std::vector<Segment> segments = collectSegments(polygons, all, totalLength);
  if (segments.empty())
    return base::Ok{};
  const auto cells = buildCells(segments, all, totalLength);
  std::uint64_t pairs = 0;
  for (std::size_t begin = 0, end = 0; begin < cells.size(); begin = end) {
    while (end < cells.size() && cells[end].first == cells[begin].first)
      ++end;
    const std::uint64_t k = end - begin;
    pairs += k * (k - 1) / 2;
  }
  if (pairs > maxPairTests)
    return makeError(ErrorCode::kLimitExceeded,
                     "coastline: too many segments close together to check for crossings (" +
                         std::to_string(pairs) + " segment pairs, the limit is " +
                         std::to_string(maxPairTests) + "); simplify the coastline");
  for (std::size_t begin = 0, end = 0; begin < cells.size(); begin = end) {
    while (end < cells.size() && cells[end].first == cells[begin].first)
      ++end;
    for (std::size_t i = begin; i < end; ++i)
      for (std::size_t j = i + 1; j < end; ++j) {
        const Segment& s = segments[cells[i].second]; // lower id: earlier in the input
        const Segment& t = segments[cells[j].second];
        if (!s.box.intersects(t.box) || adjacent(s, t))
          continue;
        if (geometry::segmentsIntersect(s.a, s.b, t.a, t.b))
          return crossingError(polygons, s, t);
      }
  }
  return base::Ok{};
}

/// Point-in-ring tests, with an index built on first use for rings large enough to need one.
class RingLocator {
public:
  explicit RingLocator(const std::vector<ParsedPolygon>& polygons) : polygons_(polygons) {
    std::size_t count = 0;
    for (const ParsedPolygon& p : polygons) {
      firstRing_.push_back(count);
      count += p.rings.size();
    }
    indexes_.resize(count);
  }

  bool inside(std::size_t polygon, std::size_t ring, Vec2 p) {
    const geometry::Ring& vertices = polygons_[polygon].rings[ring].vertices;
    if (vertices.size() <= 64)
      return geometry::contains(vertices, p);
    auto& index = indexes_[firstRing_[polygon] + ring];
    if (!index)
      index = std::make_unique<geometry::PolygonIndex>(
          geometry::MultiPolygon{geometry::Polygon{vertices, {}}});
    return index->contains(p);
  }

  /// Inside the outer ring and outside every hole of `polygon`.
  bool insidePolygon(std::size_t polygon, Vec2 p) {
    if (!inside(polygon, 0, p))
      return false;
    const auto& rings = polygons_[polygon].rings;
    for (std::size_t h = 1; h < rings.size(); ++h)
      if (geometry::bounds(rings[h].vertices).contains(p) && inside(polygon, h, p))
        return false;
    return true;
  }

private:
  const std::vector<ParsedPolygon>& polygons_;
  std::vector<std::size_t> firstRing_;
  std::vector<std::unique_ptr<geometry::PolygonIndex>> indexes_;
};

/// Calls fn(i, j), i < j, for every pair of intersecting boxes (sweep along x).
template <class Fn> base::Status forOverlappingBoxes(const std::vector<Aabb>& boxes, Fn&& fn) {
  std::vector<std::size_t> order(boxes.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return boxes[a].min.x < boxes[b].min.x; });
  for (std::size_t a = 0; a < order.size(); ++a)
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const std::size_t i = order[a], j = order[b];
      if (boxes[j].min.x > boxes[i].max.x)
        break;
      if (!boxes[i].intersects(boxes[j]))
        continue;
      STRAHLER_RETURN_IF_ERROR(fn(std::min(i, j), std::max(i, j)));
    }
  return base::Ok{};
}

base::Status checkHoles(const std::vector<ParsedPolygon>& polygons, std::size_t p,
                        RingLocator& locator) {
  const ParsedPolygon& polygon = polygons[p];
  if (polygon.rings.size() < 2)
    return base::Ok{};
  std::vector<Aabb> boxes;
  for (const ParsedRing& ring : polygon.rings)
    boxes.push_back(geometry::bounds(ring.vertices));
  for (std::size_t h = 1; h < polygon.rings.size(); ++h)
    if (!boxContains(boxes[0], boxes[h]) ||
        !locator.inside(p, 0, polygon.rings[h].vertices.front()))
      return makeError(ErrorCode::kInvalidInput, "coastline: " + polygon.label + ", ring " +
                                                     std::to_string(h) +
                                                     ": hole is not inside its outer ring "
                                                     "(ring 0)");
  const std::vector<Aabb> holeBoxes(boxes.begin() + 1, boxes.end());
  return forOverlappingBoxes(holeBoxes, [&](std::size_t i, std::size_t j) -> base::Status {
    for (const auto& [outer, inner] : {std::pair{i + 1, j + 1}, std::pair{j + 1, i + 1}})
      if (boxContains(boxes[outer], boxes[inner]) &&
          locator.inside(p, outer, polygon.rings[inner].vertices.front()))
        return makeError(ErrorCode::kInvalidInput, "coastline: " + polygon.label + ", ring " +
                                                       std::to_string(inner) +
                                                       ": hole lies inside another hole (ring " +
                                                       std::to_string(outer) + ")");
    return base::Ok{};
  });
}

base::Status checkNesting(const std::vector<ParsedPolygon>& polygons) {
  RingLocator locator(polygons);
  for (std::size_t p = 0; p < polygons.size(); ++p)
    STRAHLER_RETURN_IF_ERROR(checkHoles(polygons, p, locator));
  std::vector<Aabb> boxes;
  for (const ParsedPolygon& polygon : polygons)
    boxes.push_back(geometry::bounds(polygon.rings[0].vertices));
  return forOverlappingBoxes(boxes, [&](std::size_t i, std::size_t j) -> base::Status {
    for (const auto& [outer, inner] : {std::pair{i, j}, std::pair{j, i}})
      if (boxContains(boxes[outer], boxes[inner]) &&
          locator.insidePolygon(outer, polygons[inner].rings[0].vertices.front()))
        return makeError(ErrorCode::kInvalidInput, "coastline: " + polygons[std::min(i, j)].label +
                                                       " and " + polygons[std::max(i, j)].label +
                                                       " overlap: " + polygons[inner].label +
                                                       " lies inside " + polygons[outer].label);
    return base::Ok{};
  });
}

} // namespace

base::Status checkRingShape(const ParsedRing& ring, const std::string& where) {
  const geometry::Ring& v = ring.vertices;
  const std::size_t m = v.size();
  if (m < 3)
    return makeError(ErrorCode::kInvalidInput,
                     where + ": ring has only " + std::to_string(m) +
                         " distinct positions, a ring needs at least 3 distinct corners");
  for (std::size_t k = 0; k < m; ++k) {
    const Vec2 in = v[k] - v[(k + m - 1) % m];
    const Vec2 out = v[(k + 1) % m] - v[k];
    if (geometry::cross(in, out) == 0.0 && geometry::dot(in, out) < 0.0)
      return makeError(ErrorCode::kInvalidInput,
                       where + ": ring intersects itself: it doubles back at position " +
                           std::to_string(ring.positions[k]) + " (a zero-width spike)");
  }
  return base::Ok{};
}

base::Status checkTopology(const std::vector<ParsedPolygon>& polygons, std::uint64_t maxPairTests) {
  STRAHLER_RETURN_IF_ERROR(checkCrossings(polygons, maxPairTests));
  // A ring that crosses nothing encloses some area; this only guards against rounding.
  for (const ParsedPolygon& polygon : polygons)
    for (std::size_t r = 0; r < polygon.rings.size(); ++r)
      if (geometry::signedArea(polygon.rings[r].vertices) == 0.0)
        return makeError(ErrorCode::kInvalidInput, "coastline: " + polygon.label + ", ring " +
                                                       std::to_string(r) + ": ring has zero area");
  return checkNesting(polygons);
}

} // namespace strahler::input::detail
