#pragma once

#include "strahler/construction/world.h"
#include "strahler/geometry/aabb.h"
#include "strahler/geometry/projection.h"
#include "strahler/tiling/tile_scheme.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace strahler::tiling {

/// Where a world has water over a longitude/latitude box: its sea and lakes (everything off
/// its land) and the surface of every river at least one mask cell wide.
class WaterMask {
public:
  /// Cells per side of a full mask (Cesium's watermask extension).
  static constexpr int kSize = 256;
  /// Value of a water cell (land is 0).
  static constexpr std::uint8_t kWater = 255;

  /// A mask maker over `world` (which must outlive it), seen through `projection`.
  WaterMask(const construction::World& world, const geometry::LocalProjection& projection);

  /// The mask of `lonLat` (min = west/south, degrees): one byte (0 or kWater) when the box is
  /// all land or all water, else kSize² bytes, row 0 north, column 0 west, each the value at
  /// its cell's centre.
  std::vector<std::uint8_t> of(const geometry::Aabb& lonLat) const;
  /// The mask at the samples of `grid` (a raster grid: rows of points running west to east):
  /// grid.width · grid.height bytes, 0 or kWater, with the rivers at least as wide as the
  /// sample's row spacing. A function of each sample alone: grids sharing samples agree.
  std::vector<std::uint8_t> ofGrid(const SampleGrid& grid) const;

private:
  /// kWater or 0 when the local box `outline` is all water or all land (no shore near, no
  /// river `cell` m wide), else nothing.
  std::optional<std::uint8_t> uniform(const geometry::Aabb& outline, double cell) const;
  /// Sets the cells of `mask` (`width` × `height`, row-major) off the land (sea and lakes) to
  /// kWater.
  void addSeaAndLakes(const std::vector<geometry::Vec2>& cells, int width, int height,
                      std::vector<std::uint8_t>& mask) const;
  /// A cell's side (m): the mean of its north-south and, at the box's middle latitude,
  /// east-west extents. A river shows when it is at least that wide.
  static double cellMetres(const geometry::Aabb& lonLat) noexcept;
  /// True when a river at least `width` wide reaches the local box.
  bool anyRiver(const geometry::Aabb& local, double width) const;
  /// Marks the cells of `mask` within half a channel width of a river of the box at least
  /// `cellMetres` wide.
  void addRivers(const geometry::Aabb& lonLat, double cellMetres,
                 const std::vector<geometry::Vec2>& cells, std::vector<std::uint8_t>& mask) const;

  const construction::World& world_;
  geometry::LocalProjection projection_;
};

} // namespace strahler::tiling
