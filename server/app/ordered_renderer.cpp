#include "ordered_renderer.h"

#include "hilbert_tile_id.h"

#include <algorithm>
#include <exception>

namespace strahler::app {

using base::ErrorCode;
using base::makeError;

OrderedRenderer::OrderedRenderer(const TileService& service, RenderJob job,
                                 const std::vector<std::uint64_t>& ids)
    : service_(service), job_(job), ids_(ids),
      slots_(32 * static_cast<std::size_t>(std::max(1, job.threads))) {
  for (int t = 0; t < job.threads; ++t)
    workers_.emplace_back([this] { work(); });
}

OrderedRenderer::~OrderedRenderer() {
  stop();
  for (std::thread& w : workers_)
    w.join();
}

std::optional<std::string> OrderedRenderer::take(std::chrono::milliseconds wait) {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, wait, [&] { return stopped_ || slot(taken_).has_value(); });
  if (stopped_ || !slot(taken_))
    return std::nullopt;
  std::string bytes = std::move(*slot(taken_));
  slot(taken_).reset();
  ++taken_;
  changed_.notify_all();
  return bytes;
}

void OrderedRenderer::stop() {
  std::lock_guard lock(mutex_);
  stopped_ = true;
  changed_.notify_all();
}

std::optional<base::Error> OrderedRenderer::failure() {
  std::lock_guard lock(mutex_);
  return failure_;
}

void OrderedRenderer::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(
        lock, [&] { return stopped_ || next_ >= ids_.size() || next_ < taken_ + slots_.size(); });
    if (stopped_ || next_ >= ids_.size())
      return;
    const std::size_t i = next_++;
    lock.unlock();
    base::Result<std::string> bytes = render(ids_[i]);
    lock.lock();
    if (bytes) {
      slot(i) = std::move(bytes).value();
    } else if (!failure_) {
      failure_ = bytes.error();
      stopped_ = true;
    }
    changed_.notify_all();
  }
}

base::Result<std::string> OrderedRenderer::render(std::uint64_t id) const {
  const archive::TileCoord c = archive::tileIdToZxy(id);
  TileRequest request;
  request.tile = {c.z, c.x, c.y};
  request.format = job_.format;
  request.options.size = job_.size;
  request.options.gzip = job_.gzip;
  request.options.layer = job_.layer;
  try {
    STRAHLER_ASSIGN_OR_RETURN(RenderedTile tile, service_.render(request));
    return std::move(tile.bytes);
  } catch (const std::exception& e) { // e.g. bad_alloc: fail the export, not the process
    return makeError(ErrorCode::kInternal, "tile " + std::to_string(c.z) + "/" +
                                               std::to_string(c.x) + "/" + std::to_string(c.y) +
                                               ": " + e.what());
  }
}

} // namespace strahler::app
