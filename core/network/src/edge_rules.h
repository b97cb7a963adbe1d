#pragma once

#include "strahler/geometry/polygon_index.h"

namespace strahler::network::detail {

/// True when the first edge of a tree, from `mouth` on the shore to `child`, is acceptable:
/// child inside the land and more than `delta` from Γ, and the edge leaves the shore at once
/// (it may touch Γ only at the mouth itself).
inline bool mouthEdgeValid(const geometry::PolygonIndex& land, geometry::Vec2 mouth,
                           geometry::Vec2 child, double delta) {
  if (!land.contains(child))
    return false;
  if (land.distanceToBoundary(child, delta + 1.0) <= delta)
    return false;
  // The half of the edge near the child keeps the clearance; the whole edge, bar its first
  // few percent, must not touch the shore.
  if (land.segmentNearBoundary(geometry::lerp(mouth, child, 0.5), child, delta))
    return false;
  return !land.segmentNearBoundary(geometry::lerp(mouth, child, 0.05), child, 0.0);
}

/// True when an inner edge [from, child] is acceptable against Γ: child inside the land and
/// the whole edge more than `delta` from Γ.
inline bool innerEdgeValid(const geometry::PolygonIndex& land, geometry::Vec2 from,
                           geometry::Vec2 child, double delta) {
  if (!land.contains(child))
    return false;
  return !land.segmentNearBoundary(from, child, delta);
}

} // namespace strahler::network::detail
