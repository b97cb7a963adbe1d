#pragma once

#include "tile_service.h"

#include "strahler/base/result.h"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace strahler::app {

/// What to render for each tile of an export.
struct RenderJob {
  TileFormat format = TileFormat::kTerrainRgb;
  int size = 0; ///< 0: the format's default.
  int threads = 1;
  bool gzip = false;  ///< Gzip the bytes (vector tiles in archives).
  LayerOptions layer; ///< TileFormat::kLayerPng: the layer and its parameters.
};

/// Tiles rendered on worker threads and taken in plan order by one writer thread: workers
/// claim the next index, at most 32 per thread ahead of the writer, and leave the bytes in the
/// index's slot. So the archive does not depend on the thread count.
class OrderedRenderer {
public:
  /// Starts `job.threads` workers on the tiles `ids` (PMTiles tile ids, kept by reference).
  OrderedRenderer(const TileService& service, RenderJob job, const std::vector<std::uint64_t>& ids);
  /// Stops the workers after their current tile and joins them.
  ~OrderedRenderer();
  OrderedRenderer(const OrderedRenderer&) = delete;
  OrderedRenderer& operator=(const OrderedRenderer&) = delete;

  /// The bytes of the next tile in plan order once rendered; nothing after a worker's error
  /// (see failure()), after stop(), or while it is not ready within `wait`.
  std::optional<std::string> take(std::chrono::milliseconds wait);
  /// Makes the workers stop after their current tile.
  void stop();
  /// The first render error, if any.
  std::optional<base::Error> failure();

private:
  std::optional<std::string>& slot(std::size_t i) { return slots_[i % slots_.size()]; }

  void work();
  base::Result<std::string> render(std::uint64_t id) const;

  const TileService& service_;
  RenderJob job_;
  const std::vector<std::uint64_t>& ids_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::optional<std::string>> slots_;
  std::size_t next_ = 0;  ///< Next index a worker claims.
  std::size_t taken_ = 0; ///< Next index the writer takes.
  bool stopped_ = false;
  std::optional<base::Error> failure_;
  std::vector<std::thread> workers_; ///< Last: started once everything above exists.
};

} // namespace strahler::app
