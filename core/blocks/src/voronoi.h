#pragma once

#include "tagged_ring.h"

#include "strahler/blocks/block_set.h"
#include "strahler/geometry/aabb.h"
#include "strahler/geometry/vec2.h"

#include <vector>

namespace strahler::blocks::detail {

/// The Voronoi diagram of a set of sites, every cell clipped to a frame box.
struct VoronoiDiagram {
  std::vector<VoronoiVertex> vertices; ///< One per Delaunay triangle, sorted by their sites.
  std::vector<TaggedRing> cells;       ///< cells[i] belongs to site i: convex, CCW.
};

/// Voronoi diagram of `sites`, which must be pairwise distinct, finite and inside `frame`.
/// Works for any number of sites, collinear ones included (cells are then strips).
VoronoiDiagram buildVoronoi(const std::vector<geometry::Vec2>& sites, const geometry::Aabb& frame);

} // namespace strahler::blocks::detail
