#pragma once

#include "strahler/geometry/aabb.h"
#include "strahler/geometry/grid_index.h"
#include "strahler/geometry/polygon.h"

#include <cstdint>
#include <vector>

namespace strahler::blocks::detail {

/// Intersects convex cells with a fixed multipolygon (land with lakes) in time that depends
/// on the boundary near each cell, not on the size of the rings.
///
/// Each ring is cut into runs of consecutive segments with a bounding-box tree. For a cell,
/// the runs far from its box are replaced by a short detour around the box that sweeps the
/// same angle around it, which keeps the ring's winding number over the cell; the small local
/// ring is then clipped with geometry::clipToConvex and has the exact area of the full clip.
class LandClipper {
public:
  /// Prepares the rings of `land`, which must outlive the clipper.
  explicit LandClipper(const geometry::MultiPolygon& land);

  /// cell ∩ land for a convex counter-clockwise `cell`: one polygon per land polygon the cell
  /// overlaps (outer counter-clockwise, holes clockwise). Like clipToConvex, pieces the cell
  /// cuts apart may stay joined by zero-width bridges along the cell border.
  geometry::MultiPolygon clip(const geometry::Ring& cell) const;

private:
  struct RingTree {
    const geometry::Ring* ring = nullptr;
    std::uint32_t polygon = 0;         ///< Index of the land polygon.
    bool hole = false;                 ///< True for a lake shore.
    std::size_t leaves = 0;            ///< Number of leaf runs of segments.
    std::vector<geometry::Aabb> boxes; ///< Implicit binary tree over the leaves; [0] = all.
  };
  /// One ring's part in a cell: the whole cell, nothing, or a clipped ring.
  struct RingClip {
    geometry::Ring ring;
    bool wholeCell = false;
  };

  void addRing(const geometry::Ring& ring, std::uint32_t polygon, bool hole);
  void buildTree(RingTree& tree, std::size_t node, std::size_t lo, std::size_t hi) const;
  std::vector<std::uint32_t> ringsNear(const geometry::Aabb& box) const;
  RingClip clipRing(const RingTree& tree, const geometry::Ring& cell,
                    const geometry::Aabb& box) const;
  void clipPolygon(const std::uint32_t* first, const std::uint32_t* last,
                   const geometry::Ring& cell, const geometry::Aabb& box,
                   geometry::MultiPolygon& out) const;

  std::vector<RingTree> trees_;
  geometry::GridIndex grid_; ///< Ring ids by bounding box.
};

} // namespace strahler::blocks::detail
