#pragma once

#include "strahler/construction/world.h"
#include "strahler/quality/drainage.h"

#include <vector>

namespace strahler::quality {

/// Whether rasterizeWorld burns the river centrelines into the heights.
enum class RiverBurning { kBurn, kNone };

/// Samples a world's heights on a raster of `cellSize` metres over its land (plus a 1 km
/// margin), classifying cells as land, shore (land within half a cell of the shoreline), sea or
/// lake, on `threads` threads (same result for
/// any count). With kBurn (the drainage check's raster) rivers are then burnt in by
/// burnRivers; relief figures take kNone, the terrain as it is.
HeightRaster rasterizeWorld(const construction::World& world, double cellSize, int threads = 1,
                            RiverBurning burning = RiverBurning::kBurn);

/// The number of cells rasterizeWorld's raster of `cellSize` metres has for `world`.
double worldRasterCells(const construction::World& world, double cellSize);

/// Burns rivers into a rasterizeWorld raster (as hydrological DEM preparation does with a vector
/// stream network): every cell a river centreline crosses takes the centreline's height if
/// that is lower, because a 30 m cell cannot resolve a 4–40 m channel, and a channel sampled
/// at isolated cells would read as a chain of pits.
void burnRivers(const construction::World& world, HeightRaster& raster);

/// The centreline of one of the world's rivers, upstream first, ending at its first point in
/// the water; fewer than 2 points when it starts in the water.
std::vector<geometry::Vec2> riverCentreline(const construction::World& world,
                                            const primitives::RiverPrimitive& river);

/// The centrelines of a world's rivers, upstream first, each ending at its first point in the
/// water (a few curves touch the shore just before their mouth).
std::vector<std::vector<geometry::Vec2>> riverCentrelines(const construction::World& world);

} // namespace strahler::quality
