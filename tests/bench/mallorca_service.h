#pragma once
// The world the tile benchmarks share, and the place they look at.

#include "test_worlds.h"
#include "tile_service.h"

#include "strahler/construction/world_builder.h"

namespace strahler::bench {

/// The tile service of Mallorca with default params, generated once per process.
inline const app::TileService& mallorcaService() {
  static const app::TileService s(
      construction::generateWorldData(test_support::mallorcaSpec(), "bench").value());
  return s;
}

/// The centre of Mallorca's Serra de Tramuntana (its highest relief), degrees.
inline constexpr double kTramuntanaLon = 2.75, kTramuntanaLat = 39.78;

} // namespace strahler::bench
