#include "strahler/geometry/polygon_index.h"

#include "strahler/geometry/distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strahler::geometry {

PolygonIndex::PolygonIndex(MultiPolygon polygons, double cellSize)
    : polygons_(std::move(polygons)) {
  for (const Polygon& p : polygons_) {
    rings_.push_back(&p.outer);
    ringIsHole_.push_back(false);
    for (const Ring& h : p.holes) {
      rings_.push_back(&h);
      ringIsHole_.push_back(true);
    }
  }
  double totalLength = 0.0;
  for (std::uint32_t r = 0; r < rings_.size(); ++r) {
    const Ring& ring = *rings_[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      segments_.push_back({a, b, r});
      totalLength += distance(a, b);
      bounds_.add(a);
    }
  }
  if (bounds_.empty())
    bounds_.add(Vec2{0, 0});
  const double meanLength = segments_.empty() ? 1.0 : totalLength / double(segments_.size());
  if (cellSize <= 0.0) {
    const Vec2 size = bounds_.size();
    const double byArea = std::sqrt(std::max(size.x * size.y, 1.0) /
                                    double(std::max<std::size_t>(segments_.size(), 1)));
    cellSize = std::max({4.0 * meanLength, byArea, 1.0});
  }
  grid_ = GridIndex(bounds_, cellSize);
  for (std::uint32_t i = 0; i < segments_.size(); ++i) {
    Aabb box;
    box.add(segments_[i].a);
    box.add(segments_[i].b);
    grid_.insert(box, i);
  }
  bandHeight_ = grid_.cellSize();
  const auto bandCount = static_cast<std::size_t>(std::floor(bounds_.size().y / bandHeight_)) + 1;
  bands_.resize(bandCount);
  for (std::uint32_t i = 0; i < segments_.size(); ++i) {
    const double y0 = std::min(segments_[i].a.y, segments_[i].b.y) - bounds_.min.y;
    const double y1 = std::max(segments_[i].a.y, segments_[i].b.y) - bounds_.min.y;
    const auto b0 = static_cast<std::size_t>(std::max(0.0, std::floor(y0 / bandHeight_)));
    const auto b1 = std::min(bandCount - 1, static_cast<std::size_t>(std::floor(y1 / bandHeight_)));
    for (std::size_t b = b0; b <= b1; ++b)
      bands_[b].push_back(i);
  }
}

bool PolygonIndex::contains(Vec2 p) const noexcept {
  if (!bounds_.contains(p))
    return false;
  const auto band =
      std::min(bands_.size() - 1, static_cast<std::size_t>((p.y - bounds_.min.y) / bandHeight_));
  bool inside = false;
  for (std::uint32_t i : bands_[band]) {
    const Vec2 a = segments_[i].a, b = segments_[i].b;
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
      if (p.x < x)
        inside = !inside;
    }
  }
  return inside;
}

BoundaryHit PolygonIndex::nearestBoundary(Vec2 p, double maxDistance) const noexcept {
  BoundaryHit hit{maxDistance, p, -1};
  double best2 = maxDistance * maxDistance;
  const double cell = grid_.cellSize();
  // Expanding rings of cells; p outside the grid is clamped to a border cell, which keeps
  // (r - 1) cells a lower bound of the distance to ring r.
  for (int r = 0;; ++r) {
    // Every point in ring r is at least (r - 1) cells away from p.
    const double ringMin = (r - 1) * cell;
    if (r > 0 && ringMin > 0 && ringMin * ringMin > best2)
      break;
    const bool inGrid = grid_.queryRing(p, r, [&](std::uint32_t i) {
      const Vec2 q = closestPointOnSegment(p, segments_[i].a, segments_[i].b);
      const double d2 = lengthSquared(q - p);
      if (d2 < best2) {
        best2 = d2;
        hit.point = q;
        hit.segment = i;
      }
    });
    if (!inGrid)
      break; // every further ring lies outside the grid too
  }
  if (hit.segment >= 0)
    hit.distance = std::sqrt(best2);
  return hit;
}

bool PolygonIndex::segmentNearBoundary(Vec2 a, Vec2 b, double clearance) const noexcept {
  Aabb box;
  box.add(a);
  box.add(b);
  box = box.expanded(clearance);
  bool near = false;
  grid_.query(box, [&](std::uint32_t i) {
    const double d = segmentSegmentDistance(a, b, segments_[i].a, segments_[i].b);
    if (d < clearance || (clearance == 0.0 && d == 0.0))
      near = true;
    return !near;
  });
  return near;
}

} // namespace strahler::geometry
