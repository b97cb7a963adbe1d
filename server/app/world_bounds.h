#pragma once

#include "strahler/construction/world_data.h"

namespace strahler::app {

/// A box in WGS84 degrees.
struct LonLatBox {
  double west = 0.0, south = 0.0, east = 0.0, north = 0.0;
};

/// The bounds of the world's land, degrees: what /worlds/{id} and TileJSON report and what
/// `strahler export` covers.
LonLatBox worldBounds(const construction::WorldData& world);

} // namespace strahler::app
