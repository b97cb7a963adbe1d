#include "strahler/vegetation/web_tile.h"

#include "strahler/base/assert.h"
#include "strahler/geometry/web_mercator.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace strahler::vegetation {

using geometry::Vec2;

Vec2 tileCoordinates(const geometry::TileId& tile, Vec2 lonLat) noexcept {
  const Vec2 m = geometry::webMercatorUnit(lonLat);
  // ldexp scales by 2^z exactly, so a point's tile at zoom z + 1 is a child of its tile at z.
  return {std::ldexp(m.x, tile.z) - static_cast<double>(tile.x),
          std::ldexp(m.y, tile.z) - static_cast<double>(tile.y)};
}

Footprint webTileFootprint(const geometry::LocalProjection& projection,
                           const geometry::TileId& tile) {
  // The tile's outline through the projection; its edges bend by far less than the margin
  // between 16 samples each (the curvature radius is thousands of kilometres).
  constexpr int kEdgeSamples = 16;
  geometry::Aabb bounds;
  const double n = std::ldexp(1.0, tile.z);
  for (int k = 0; k <= kEdgeSamples; ++k) {
    const double t = static_cast<double>(k) / kEdgeSamples;
    for (Vec2 f : {Vec2{t, 0.0}, Vec2{t, 1.0}, Vec2{0.0, t}, Vec2{1.0, t}}) {
      const Vec2 unit{(static_cast<double>(tile.x) + f.x) / n,
                      (static_cast<double>(tile.y) + f.y) / n};
      bounds.add(projection.forward(geometry::lonLatOfWebMercatorUnit(unit)));
    }
  }
  bounds = bounds.expanded(0.5 + 1e-3 * std::max(bounds.size().x, bounds.size().y));
  return {bounds, [projection, tile](Vec2 p) {
            const Vec2 c = tileCoordinates(tile, projection.inverse(p));
            return std::floor(c.x) == 0.0 && std::floor(c.y) == 0.0;
          }};
}

base::Result<std::vector<Instance>> placeWebTile(std::uint64_t seed,
                                                 const geometry::LocalProjection& projection,
                                                 const geometry::TileId& tile,
                                                 const DensityField& density) {
  const SpeciesMask mask = visibleSpecies(tile.z);
  if (mask == 0)
    return base::makeError(base::ErrorCode::kOutOfRange,
                           "vegetation: no species is served at zoom " + std::to_string(tile.z));
  const std::int64_t n = std::int64_t{1} << tile.z;
  if (tile.x < 0 || tile.x >= n || tile.y < 0 || tile.y >= n)
    return base::makeError(base::ErrorCode::kOutOfRange,
                           "vegetation: tile " + std::to_string(tile.x) + "/" +
                               std::to_string(tile.y) + " is outside zoom " +
                               std::to_string(tile.z));
  std::vector<Instance> instances =
      placeInstances(seed, webTileFootprint(projection, tile), density, mask);
  STRAHLER_ASSERT(instances.size() <= maxInstancesPerWebTile(tile.z, mask),
                  "a tile above the packing bound: spacing broken");
  return instances;
}

} // namespace strahler::vegetation
