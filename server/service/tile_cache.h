#pragma once

#include "tile_status.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace strahler::service {

/// A finished, encoded tile as the cache keeps it.
struct CachedTile {
  std::string bytes;
  std::string mimeType;
  std::string etag;            ///< Strong ETag, quoted.
  std::string contentEncoding; ///< The bytes' content coding ("gzip"), "" for none.
  std::string vary;            ///< The request header fields the bytes depend on, "" for none.
  /// The header fields of the tile's response, serialised once by whoever made the tile (opaque
  /// to the cache, which only charges their bytes; may be empty).
  std::string httpFields;
  double evaluateMs = 0.0;
  double encodeMs = 0.0;
};

/// Counters of the cache, for /metrics.
struct TileCacheStats {
  std::size_t hits = 0;
  std::size_t misses = 0;
  std::size_t evictions = 0;
  /// Heap bytes held now: every string's capacity (key and tile) and each entry's bookkeeping
  /// (tile object, list and index nodes), as glibc malloc allocates them.
  std::size_t bytes = 0;
  std::size_t entries = 0;
  std::size_t inFlight = 0;     ///< Distinct tiles being computed now.
  std::size_t coalesced = 0;    ///< Requests that waited for another request's computation.
  std::size_t computations = 0; ///< Times a tile was actually computed.
  std::size_t errors = 0;       ///< Computations that ended in an error (not cached).
  std::size_t refused = 0;      ///< Requests answered kRetryLater: the work was not scheduled.
  std::size_t cancelled = 0;    ///< Computations skipped because every requester had gone.
};

/// A byte-bounded LRU of encoded tiles with single flight: concurrent requests for the same
/// key trigger one computation and all receive its result. Thread-safe.
class TileCache {
public:
  /// The result of a computation: a tile (kOk), or another status and its message (not
  /// cached).
  struct Outcome {
    std::shared_ptr<const CachedTile> tile; ///< Null unless status is kOk.
    TileStatus status = TileStatus::kOk;
    std::string message; ///< Why there is no tile; empty for kOk.
  };
  /// Computes a tile; runs outside the cache lock.
  using Compute = std::function<Outcome()>;
  /// Receives the outcome; may run on the computing thread.
  using Callback = std::function<void(const Outcome&)>;
  /// True once a requester is gone (its answer can no longer be delivered); null: never.
  using Gone = std::shared_ptr<const std::atomic<bool>>;
  /// Hands a computation to a worker; returns false when it cannot be queued (overload).
  /// Work destroyed without being run (e.g. by WorkerPool's destructor) answers kRetryLater.
  using Schedule = std::function<bool(std::function<void()> work)>;

  /// A cache holding at most `maxBytes` heap bytes (TileCacheStats::bytes; 0: nothing is kept,
  /// single flight still works). Store exactly-sized strings: capacity is what is charged.
  explicit TileCache(std::size_t maxBytes);
  ~TileCache();

  /// Delivers the tile of `key` to `callback`: at once on a hit; otherwise joins the
  /// computation in flight for `key`, or starts one through `schedule`. When `schedule`
  /// refuses (or throws, or drops the work unrun), callback and every request that joined
  /// meanwhile get kRetryLater. An exception from `compute`, or a kOk without a tile, becomes
  /// kFailed.
  /// Each callback is called exactly once, never under the cache lock (it may use the cache
  /// again); if one throws, the others are still called and the first exception propagates to
  /// whoever ran the work (swallowed for kRetryLater answers). The work holds the cache state
  /// alive, so a TileCache may be destroyed while its computations are still queued. When the work
  /// runs and every waiter's `gone` is set, nothing is computed: they get kRetryLater
  /// (cancelled).
  void get(const std::string& key, const Compute& compute, const Schedule& schedule,
           Callback callback, Gone gone = nullptr);

  /// The cached tile of `key`, now the most recently used, counted as a hit; null (and not
  /// counted) when it is not cached. A cheap first try for get(), which counts the miss.
  std::shared_ptr<const CachedTile> find(std::string_view key);

  /// Current counters.
  TileCacheStats stats() const;
  /// Heap bytes an entry of `key` and `tile` is charged: each string's capacity (none for
  /// short strings kept inside the object) as glibc malloc allocates it, plus
  /// entryOverheadBytes(). Capacity, not size: a reserved, never-shrunk buffer is held whole.
  static std::size_t chargedBytes(const std::string& key, const CachedTile& tile) noexcept;
  /// The fixed part of chargedBytes(): tile object, control block, list and index nodes.
  static std::size_t entryOverheadBytes() noexcept;
  /// The byte bound.
  std::size_t maxBytes() const noexcept;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace strahler::service
