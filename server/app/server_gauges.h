#pragma once

#include "tile_cache.h"

#include <cstddef>
#include <string>

namespace strahler::app {

/// The state of the tile server's work side at one moment, for /metrics.
struct WorkGauges {
  service::TileCacheStats cache; ///< The tile cache's counters.
  std::size_t cacheMaxBytes = 0; ///< The tile cache's byte bound.
  std::size_t queued = 0;        ///< Tile computations waiting for a worker.
  std::size_t busy = 0;          ///< Workers computing a tile.
};

/// `gauges` in the Prometheus text format (HELP, TYPE and value of each), to append to
/// service::Metrics::render()'s request counters.
std::string renderWorkGauges(const WorkGauges& gauges);

} // namespace strahler::app
