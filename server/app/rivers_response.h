#pragma once

#include "worker_pool.h"

#include "strahler/construction/world_data.h"
#include "strahler/http/http_types.h"

#include <functional>
#include <future>
#include <memory>
#include <string>

namespace strahler::app {

/// A world's rivers.geojson, as text and gzipped.
struct RiversText {
  std::shared_ptr<const std::string> plain; ///< The GeoJSON.
  std::shared_ptr<const std::string> gzip;  ///< The same, one gzip member.
};

/// Starts writing (and gzipping) the rivers.geojson of `world` on a thread of its own: a large
/// world's takes seconds, which the server does not wait for. `world` must outlive the future.
std::shared_future<RiversText> writeRiversAsync(const construction::WorldData& world);

/// How one request for rivers.geojson is answered.
struct RiversRequest {
  bool gzip = false;           ///< The client accepts gzip.
  std::string etag;            ///< The GeoJSON's ETag: a function of the world's content.
  bool currentVersion = false; ///< The URL carried the world's current version (`v`).
};

/// Answers GET rivers.geojson (route "rivers"), gzipped if `request.gzip`, with its ETag and
/// the tiles' Cache-Control (immutable for the current version only): at once when `rivers` is
/// written, else from a worker of `pool` that waits for it (503 with Retry-After when the pool
/// refuses or drops the wait), so that no I/O thread waits.
void answerRivers(const std::shared_future<RiversText>& rivers, const RiversRequest& request,
                  service::WorkerPool& pool, std::function<void(http::Response)> done);

} // namespace strahler::app
