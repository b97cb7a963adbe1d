#include "server_gauges.h"

namespace strahler::app {

std::string renderWorkGauges(const WorkGauges& w) {
  const service::TileCacheStats& s = w.cache;
  std::string g;
  auto gauge = [&](const char* name, const char* help, const char* type, double v) {
    g += std::string("# HELP ") + name + " " + help + "\n# TYPE " + name + " " + type + "\n" +
         name + " " + std::to_string(v) + "\n";
  };
  gauge("strahler_tile_cache_hits_total", "Tile cache hits.", "counter", double(s.hits));
  gauge("strahler_tile_cache_misses_total", "Tile cache misses.", "counter", double(s.misses));
  gauge("strahler_tile_cache_evictions_total", "Tiles evicted from the cache.", "counter",
        double(s.evictions));
  gauge("strahler_tile_cache_bytes", "Bytes held by the tile cache.", "gauge", double(s.bytes));
  gauge("strahler_tile_cache_max_bytes", "Byte bound of the tile cache.", "gauge",
        double(w.cacheMaxBytes));
  gauge("strahler_tile_cache_entries", "Tiles held by the tile cache.", "gauge", double(s.entries));
  gauge("strahler_tiles_in_flight", "Distinct tiles being computed.", "gauge", double(s.inFlight));
  gauge("strahler_tile_computations_total", "Tiles computed (single flight: once per key).",
        "counter", double(s.computations));
  gauge("strahler_tile_requests_coalesced_total",
        "Requests that waited for a computation in flight.", "counter", double(s.coalesced));
  gauge("strahler_tile_computations_cancelled_total",
        "Queued tile computations skipped because every client of the tile had gone.", "counter",
        double(s.cancelled));
  gauge("strahler_worker_queue_depth", "Tile computations waiting for a worker.", "gauge",
        double(w.queued));
  gauge("strahler_workers_busy", "Workers computing a tile.", "gauge", double(w.busy));
  return g;
}

} // namespace strahler::app
