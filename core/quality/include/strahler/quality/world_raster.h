#pragma once

#include "strahler/construction/world.h"
#include "strahler/quality/drainage.h"

#include <vector>

namespace strahler::quality {

/// Samples a world's heights on a raster of `cellSize` metres over its land (plus a 1 km
/// margin), classifying cells as land, sea or lake, on `threads` threads (same result for
/// any count). Rivers are then burnt in (as hydrological DEM preparation does with a vector
/// stream network): every cell a river centreline crosses takes the centreline's height if
/// that is lower, because a 30 m cell cannot resolve a 4–40 m channel, and a channel sampled
/// at isolated cells would read as a chain of pits.
HeightRaster rasterizeWorld(const construction::World& world, double cellSize, int threads = 1);

/// The centrelines of a world's rivers, upstream first, each ending at its first point in the
/// water (a few curves touch the shore just before their mouth).
std::vector<std::vector<geometry::Vec2>> riverCentrelines(const construction::World& world);

} // namespace strahler::quality
