#include "rivers_response.h"

#include "gzip.h"
#include "tile_response.h"

#include "strahler/geometry/projection.h"
#include "strahler/render/rivers_geojson.h"

#include <chrono>
#include <utility>

namespace strahler::app {
namespace {

http::Response riversResponse(const RiversText& rivers, const RiversRequest& request) {
  http::Response r;
  r.headers = {{"Content-Type", "application/geo+json"},
               {"ETag", request.etag},
               {"Cache-Control", tileCacheControl(request.currentVersion)},
               {"Vary", "Accept-Encoding"}};
  if (request.gzip)
    r.headers.emplace_back("Content-Encoding", "gzip");
  r.sharedBody = request.gzip ? rivers.gzip : rivers.plain;
  r.route = "rivers";
  return r;
}

/// A request for rivers.geojson waiting on a worker. Whatever becomes of the task (run,
/// refused, or dropped unrun at shutdown) the client gets one answer: the GeoJSON or a 503.
class RiversWaiter {
public:
  RiversWaiter(std::shared_future<RiversText> rivers, RiversRequest request,
               std::function<void(http::Response)> done)
      : rivers_(std::move(rivers)), request_(std::move(request)), done_(std::move(done)) {}
  RiversWaiter(const RiversWaiter&) = delete;
  RiversWaiter& operator=(const RiversWaiter&) = delete;
  ~RiversWaiter() {
    if (!done_)
      return;
    http::Response r = http::errorResponse(503, "the rivers are still being written");
    r.headers.emplace_back("Retry-After", "1");
    r.route = "rivers";
    std::exchange(done_, nullptr)(std::move(r));
  }

  /// Waits for the GeoJSON and sends it.
  void answer() {
    http::Response r = riversResponse(rivers_.get(), request_); // throws: the destructor's 503
    std::exchange(done_, nullptr)(std::move(r));
  }

private:
  std::shared_future<RiversText> rivers_;
  RiversRequest request_;
  std::function<void(http::Response)> done_;
};

} // namespace

std::shared_future<RiversText> writeRiversAsync(const construction::WorldData& world) {
  const geometry::LocalProjection projection(world.projectionCenter.x, world.projectionCenter.y);
  return std::async(std::launch::async,
                    [&world, projection] {
                      auto plain = std::make_shared<const std::string>(
                          render::riversGeoJson(world, projection));
                      return RiversText{plain, std::make_shared<const std::string>(
                                                   gzip::compress(*plain, gzip::Level::kFastest))};
                    })
      .share();
}

void answerRivers(const std::shared_future<RiversText>& rivers, const RiversRequest& request,
                  service::WorkerPool& pool, std::function<void(http::Response)> done) {
  if (rivers.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
    return done(riversResponse(rivers.get(), request));
  // Still being written: wait on a worker, not on this I/O thread.
  auto waiter = std::make_shared<RiversWaiter>(rivers, request, std::move(done));
  pool.submit([waiter] { waiter->answer(); }); // refused: the waiter answers 503
}

} // namespace strahler::app
