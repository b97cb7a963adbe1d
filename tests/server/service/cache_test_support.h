#pragma once

#include "tile_cache.h"

#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace strahler::service::test_support {

/// A tile of `size` bytes of `fill` (capacity `size` too), with empty MIME type and ETag.
inline std::shared_ptr<const CachedTile> makeTile(std::size_t size, char fill = 't') {
  auto tile = std::make_shared<CachedTile>();
  tile->bytes.assign(size, fill);
  return tile;
}

/// The charge of an entry of `key` holding makeTile(size).
inline std::size_t entryCharge(const std::string& key, std::size_t size) {
  return TileCache::chargedBytes(key, *makeTile(size));
}

/// A Compute that returns `tile` and counts its calls.
inline TileCache::Compute computeReturning(std::shared_ptr<const CachedTile> tile,
                                           std::shared_ptr<int> calls = nullptr) {
  return [tile = std::move(tile), calls = std::move(calls)] {
    if (calls) {
      ++*calls;
    }
    return TileCache::Outcome{tile, TileStatus::kOk, {}};
  };
}

/// Runs the work at once on the calling thread.
inline bool runInline(std::function<void()> work) {
  work();
  return true;
}

/// Keeps scheduled work until the test runs (or drops) it: single-threaded control over
/// when a computation happens.
class ManualScheduler {
public:
  /// The Schedule to hand to TileCache::get.
  TileCache::Schedule schedule() {
    return [this](std::function<void()> work) {
      works_.push_back(std::move(work));
      return true;
    };
  }
  /// Work scheduled and not yet run or dropped.
  std::size_t pending() const { return works_.size(); }
  /// Runs the oldest pending work.
  void runNext() {
    std::function<void()> work = std::move(works_.front());
    works_.erase(works_.begin());
    work();
  }
  /// Destroys every pending work unrun.
  void dropAll() { works_.clear(); }

private:
  std::vector<std::function<void()>> works_;
};

/// Thread-safe record of the outcomes delivered to callbacks. Declare it before the schedulers
/// and pools of a test: work they drop on destruction still answers its callbacks.
class OutcomeLog {
public:
  /// A callback that appends its outcome here.
  TileCache::Callback callback() {
    return [this](const TileCache::Outcome& outcome) { record(outcome); };
  }
  void record(const TileCache::Outcome& outcome) {
    {
      std::lock_guard lock(mutex_);
      outcomes_.push_back(outcome);
    }
    changed_.notify_all();
  }
  /// Waits until `count` outcomes arrived; false after `limit`.
  bool waitFor(std::size_t count, std::chrono::milliseconds limit = std::chrono::seconds(10)) {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, limit, [&] { return outcomes_.size() >= count; });
  }
  std::vector<TileCache::Outcome> outcomes() const {
    std::lock_guard lock(mutex_);
    return outcomes_;
  }

private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<TileCache::Outcome> outcomes_;
};

} // namespace strahler::service::test_support
