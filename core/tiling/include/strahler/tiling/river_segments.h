#pragma once

#include "strahler/construction/world.h"
#include "strahler/geometry/aabb.h"
#include "strahler/geometry/vec2.h"
#include "strahler/tiling/tile_scheme.h"

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace strahler::tiling {

/// One straight piece of a river's channel, local metres.
struct RiverSegment {
  geometry::Vec2 a;       ///< Upstream end.
  geometry::Vec2 b;       ///< Downstream end.
  double halfWidth = 0.0; ///< Half the channel width at the segment's middle, m.
};

/// Calls `visit` for every segment of `world`'s rivers at least `minWidth` wide (the width
/// varies linearly along a curve with the distance travelled) that comes within `margin` m of
/// the channel's edge to `box` (local metres). The one walk over river channels of the water
/// mask and the humidity layer.
void forEachRiverSegment(const construction::World& world, const geometry::Aabb& box,
                         double minWidth, double margin,
                         const std::function<void(const RiverSegment&)>& visit);

/// The samples of a raster grid (rows of points running west to east, as both raster pyramids
/// lay them) found by local box: the rows by their extent in y, the columns by binary search.
class GridRows {
public:
  /// An index over `grid` (which must outlive it).
  explicit GridRows(const SampleGrid& grid);
  /// Calls `visit(row, column)` for every sample of the grid inside `box`.
  template <class Visit> void forEachIn(const geometry::Aabb& box, Visit&& visit) const {
    const auto w = static_cast<std::size_t>(grid_.width);
    const auto [first, end] = rowsIn(box);
    for (std::size_t j = first; j < end; ++j) {
      if (rowY_[j].second < box.min.y || rowY_[j].first > box.max.y)
        continue;
      for (std::size_t i = firstAtLeast(j, box.min.x); i < w; ++i) {
        const geometry::Vec2 p = grid_.points[j * w + i];
        if (p.x > box.max.x)
          break;
        if (p.y >= box.min.y && p.y <= box.max.y)
          visit(j, i);
      }
    }
  }

private:
  /// The first column of row j whose x is at least `x`.
  std::size_t firstAtLeast(std::size_t j, double x) const;
  /// The rows [first, end) that may reach the y extent of `box` (all of them unless the rows'
  /// extents fall southward, as both raster pyramids lay them).
  std::pair<std::size_t, std::size_t> rowsIn(const geometry::Aabb& box) const;

  const SampleGrid& grid_;
  std::vector<std::pair<double, double>> rowY_; ///< Per row: its least and greatest y.
  bool southward_ = true; ///< Both ends of the rows' extents fall from row to row.
};

/// Distance² from p to the segment [a, b].
double distance2ToSegment(geometry::Vec2 p, geometry::Vec2 a, geometry::Vec2 b) noexcept;

} // namespace strahler::tiling
