#include "tagged_ring.h"

#include <algorithm>
#include <utility>

namespace strahler::blocks::detail {
namespace {

using geometry::Vec2;

/// Where segment [p, q] crosses the line, given signed distances dp and dq of opposite signs.
/// The segment is taken in a fixed (lexicographic) direction so that the two cells sharing
/// an edge compute bit-identical points.
Vec2 crossing(Vec2 p, double dp, Vec2 q, double dq, Vec2 origin, Vec2 normal) {
  if (q.x < p.x || (q.x == p.x && q.y < p.y)) {
    std::swap(p, q);
    std::swap(dp, dq);
  }
  Vec2 x = geometry::lerp(p, q, dp / (dp - dq));
  // Axis-aligned lines (the frame, grid bisectors) get their coordinate exactly.
  if (normal.y == 0.0)
    x.x = origin.x;
  if (normal.x == 0.0)
    x.y = origin.y;
  return x;
}

} // namespace

TaggedRing boxRing(const geometry::Aabb& box) {
  TaggedRing ring;
  ring.push(box.min, kNoVertex, NodeId::invalid());
  ring.push({box.max.x, box.min.y}, kNoVertex, NodeId::invalid());
  ring.push(box.max, kNoVertex, NodeId::invalid());
  ring.push({box.min.x, box.max.y}, kNoVertex, NodeId::invalid());
  return ring;
}

void clipHalfPlane(TaggedRing& ring, Vec2 origin, Vec2 normal, NodeId neighbour) {
  const std::size_t n = ring.size();
  std::vector<double> side(n);
  bool anyOut = false;
  for (std::size_t i = 0; i < n; ++i) {
    side[i] = geometry::dot(ring.points[i] - origin, normal);
    anyOut |= side[i] > 0.0;
  }
  if (!anyOut)
    return;
  TaggedRing out;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const Vec2 p = ring.points[i], q = ring.points[j];
    const double dp = side[i], dq = side[j];
    if (dp <= 0.0) {
      // A corner on the line whose successor is cut away starts the new edge itself.
      const bool leaves = dq > 0.0;
      out.push(p, ring.vertices[i], leaves && dp == 0.0 ? neighbour : ring.neighbours[i]);
      if (leaves && dp < 0.0)
        out.push(crossing(p, dp, q, dq, origin, normal), kNoVertex, neighbour);
    } else if (dq < 0.0) {
      out.push(crossing(p, dp, q, dq, origin, normal), kNoVertex, ring.neighbours[i]);
    }
  }
  ring = std::move(out);
}

void dropCoincidentCorners(TaggedRing& ring, const std::vector<VoronoiVertex>& vertices) {
  const std::size_t n = ring.size();
  if (n < 2)
    return;
  auto coincide = [&](std::size_t i, std::size_t j) {
    if (ring.points[i] == ring.points[j])
      return true;
    const std::uint32_t a = ring.vertices[i], b = ring.vertices[j];
    if (a == kNoVertex || b == kNoVertex)
      return false;
    const double tolerance = kCoincidentCorner * std::min(vertices[a].radius, vertices[b].radius);
    return geometry::distance(ring.points[i], ring.points[j]) <= tolerance;
  };
  TaggedRing out;
  for (std::size_t i = 0; i < n; ++i) {
    // Never drop the last survivor of a ring whose corners all coincide.
    if (coincide(i, (i + 1) % n) && !(i + 1 == n && out.size() == 0))
      continue;
    out.push(ring.points[i], ring.vertices[i], ring.neighbours[i]);
  }
  ring = std::move(out);
}

} // namespace strahler::blocks::detail
