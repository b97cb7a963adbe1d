#pragma once

#include "strahler/base/result.h"
#include "strahler/geometry/projection.h"
#include "strahler/geometry/tile_id.h"
#include "strahler/vegetation/placement.h"

#include <cstdint>
#include <vector>

namespace strahler::vegetation {

/// Position in a Web Mercator tile: (0, 0) at its north-west corner, (1, 1) at the
/// south-east one, x east, y south (pixel coordinates divided by the tile size).
geometry::Vec2 tileCoordinates(const geometry::TileId& tile, geometry::Vec2 lonLat) noexcept;

/// The footprint of a Web Mercator tile seen through a world's projection. A point belongs to
/// the tile whose floor(tileCoordinates · 2^z) it falls in, so the tiles of a zoom partition
/// the plane and a tile owns exactly the points of its four children.
Footprint webTileFootprint(const geometry::LocalProjection& projection,
                           const geometry::TileId& tile);

/// The instances of a Web Mercator tile: placeInstances() over webTileFootprint() for the
/// species visibleSpecies(z) serves, at most maxInstancesPerWebTile(z) of them. kOutOfRange
/// for a zoom without vegetation (below every species' minZoom or past kMaxVegetationZoom)
/// and for x or y outside [0, 2^z).
base::Result<std::vector<Instance>> placeWebTile(std::uint64_t seed,
                                                 const geometry::LocalProjection& projection,
                                                 const geometry::TileId& tile,
                                                 const DensityField& density);

} // namespace strahler::vegetation
