#pragma once

#include "memory_trimmer.h"
#include "metrics.h"
#include "route_parser.h"
#include "router.h"
#include "tile_cache.h"
#include "tile_request.h"
#include "worker_pool.h"

#include "strahler/construction/world_data.h"
#include "strahler/http/http_types.h"

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace strahler::app {

/// Settings of the tile server's work side.
struct TileServerOptions {
  int workers = 2;                     ///< Threads computing tiles.
  std::size_t maxQueued = 256;         ///< Tile computations waiting before 503.
  std::size_t cacheBytes = 256u << 20; ///< Byte bound of the encoded-tile LRU.
  std::string webRoot;                 ///< Folder of the built viewer (index.html); "" if none.
  /// How often freed heap memory is returned to the system after tiles were computed
  /// (MemoryTrimmer); 0 never.
  std::chrono::milliseconds trimPeriod{1000};
  /// Origin and path prefix of absolute URLs (TileJSON's tiles), from parsePublicUrl(); "" to
  /// use a trusted proxy's X-Forwarded-* or the address each client connected to (see
  /// requestOrigin()). Never the Host header.
  std::string publicUrl;
};

/// The endpoints of DESIGN.md's server contract over a set of worlds: /, /worlds,
/// /worlds/{id}, tilejson.json, tiles (Web Mercator and local), rivers.geojson, /health and
/// /metrics. It routes (router.h) and owns the shared work side; each endpoint's answer is made
/// in its own file. Tiles are computed on a bounded worker pool through a single-flight LRU
/// cache; everything else is answered on the calling (I/O) thread (rivers.geojson on a worker
/// while it is still being written). docs/architecture.md follows a tile request through it.
/// Thread-safe.
class TileServer {
public:
  /// A server over `worlds` (id, data); ids must be unique URL segments.
  TileServer(std::vector<std::pair<std::string, construction::WorldData>> worlds,
             TileServerOptions options);
  ~TileServer();

  /// The http::Handler: answers `request` through `done`.
  void handle(const http::Request& request, std::function<void(http::Response)> done);
  /// The http::RequestObserver: records a finished request in the metrics.
  void observe(const std::string& route, int status, std::size_t bytes, double ms);
  /// Waits for queued tile computations to finish (graceful shutdown).
  void drain();
  /// Shutdown: drops the queued tile computations (their requests get 503 with Retry-After)
  /// and refuses new ones; computations already running finish. Returns at once.
  void cancelQueued();

  /// The world ids served, in order.
  std::vector<std::string> worldIds() const;
  /// The metrics (for tests).
  const service::Metrics& metrics() const noexcept { return metrics_; }
  /// The tile cache (for tests).
  const service::TileCache& cache() const noexcept { return cache_; }

private:
  struct ServedWorld;
  const ServedWorld* find(const std::string& id) const;
  /// The endpoints under /worlds/{id}: `endpoint` is routeOf(target.segments).
  void handleWorld(const ServedWorld& world, Endpoint endpoint, const ParsedTarget& target,
                   const http::Request& request, std::function<void(http::Response)> done);
  http::Response tileJson(const ServedWorld& world, const http::Request& request,
                          const LayerOptions* layer = nullptr) const;
  /// The tile pipeline, after the route became a TileRequest: grid → 304 → cache (single
  /// flight) → a worker's TileService::render → outcome → tileResponse(). `currentVersion`:
  /// the URL carried the world's version (immutable), else a short max-age.
  void tile(const ServedWorld& world, const TileRequest& tile, const http::Request& request,
            bool currentVersion, std::function<void(http::Response)> done);
  http::Response metricsResponse() const;

  std::vector<std::unique_ptr<ServedWorld>> worlds_;
  TileServerOptions options_;
  service::Metrics metrics_;
  service::TileCache cache_;
  service::MemoryTrimmer trimmer_;
  service::WorkerPool pool_;
};

} // namespace strahler::app
