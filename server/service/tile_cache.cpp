#include "tile_cache.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <list>
#include <mutex>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace strahler::service {

namespace {

using Outcome = TileCache::Outcome;
using Callback = TileCache::Callback;

/// Heap bytes of one allocation of `n` bytes under glibc malloc: n plus its 8-byte header,
/// rounded up to 16, at least 32.
constexpr std::size_t mallocChunk(std::size_t n) {
  return std::max<std::size_t>(32, (n + 8 + 15) / 16 * 16);
}

/// Heap bytes behind a string: its capacity (not its size: a buffer reserved larger and never
/// shrunk holds all of it), none when the characters sit inside the object (short strings).
std::size_t heapBytes(const std::string& text) noexcept {
  return text.capacity() > std::string().capacity() ? mallocChunk(text.capacity() + 1) : 0;
}

/// The requests waiting for one computation. Its identity tells a finishing computation
/// whether the flight it belongs to is still the one registered for its key.
struct Flight {
  std::vector<Callback> waiters;
  std::vector<TileCache::Gone> gone; ///< Beside waiters; null for a waiter never gone.
};

struct Entry {
  std::string key;
  std::shared_ptr<const CachedTile> tile;
  std::size_t bytes = 0;
};

/// Calls every waiter even when one throws; returns the first exception.
std::exception_ptr deliver(const std::vector<Callback>& waiters, const Outcome& outcome) {
  std::exception_ptr first;
  for (const Callback& callback : waiters) {
    try {
      callback(outcome);
    } catch (...) {
      if (!first) {
        first = std::current_exception();
      }
    }
  }
  return first;
}

Outcome errorOutcome(TileStatus status, std::string message) {
  return Outcome{nullptr, status, std::move(message)};
}

/// Runs `compute`, turning exceptions and tile-less successes into kFailed outcomes.
Outcome computeSafely(const TileCache::Compute& compute) {
  try {
    Outcome outcome = compute();
    if (outcome.status != TileStatus::kOk) {
      outcome.tile = nullptr;
    } else if (!outcome.tile) {
      return errorOutcome(TileStatus::kFailed, "tile computation produced no tile");
    }
    return outcome;
  } catch (const std::exception& e) {
    return errorOutcome(TileStatus::kFailed, std::string("tile computation failed: ") + e.what());
  } catch (...) {
    return errorOutcome(TileStatus::kFailed, "tile computation failed");
  }
}

/// The cache state. Shared with the scheduled computations so that they may outlive the
/// TileCache object (a worker pool may still hold them).
struct CacheCore {
  explicit CacheCore(std::size_t bound) : maxBytes(bound) {}

  const std::size_t maxBytes;
  mutable std::mutex mutex;
  std::list<Entry> lru; ///< Most recently used first.
  std::unordered_map<std::string_view, std::list<Entry>::iterator> index; ///< Keys live in lru.
  std::unordered_map<std::string, std::shared_ptr<Flight>> flights;
  TileCacheStats counters; ///< entries and inFlight are derived in stats().

  /// Under the lock: the cached tile of `key`, now the most recently used, or null.
  std::shared_ptr<const CachedTile> lookup(std::string_view key) {
    const auto found = index.find(key);
    if (found == index.end()) {
      return nullptr;
    }
    lru.splice(lru.begin(), lru, found->second);
    ++counters.hits;
    return found->second->tile;
  }

  /// Under the lock: adds `callback` to the flight of `key`. Returns the flight when this
  /// call started it (the caller must schedule it), null when it joined one in progress.
  std::shared_ptr<Flight> join(const std::string& key, Callback&& callback,
                               TileCache::Gone&& gone) {
    ++counters.misses;
    std::shared_ptr<Flight>& flight = flights[key];
    const bool joined = flight != nullptr;
    if (!joined) {
      flight = std::make_shared<Flight>();
    }
    flight->waiters.push_back(std::move(callback));
    flight->gone.push_back(std::move(gone));
    if (joined) {
      ++counters.coalesced;
      return nullptr;
    }
    return flight;
  }

  /// Answers the waiters of `flight` with kRetryLater instead of computing when every one of them
  /// is gone; true when it did (or the flight was already answered).
  bool cancelIfNobodyWaits(const std::string& key, const std::shared_ptr<Flight>& flight) {
    std::vector<Callback> waiters;
    {
      std::lock_guard lock(mutex);
      for (const TileCache::Gone& gone : flight->gone) {
        if (!gone || !gone->load(std::memory_order_relaxed)) {
          return false;
        }
      }
      waiters = takeWaiters(key, flight);
      ++counters.cancelled;
    }
    (void)deliver(waiters,
                  errorOutcome(TileStatus::kRetryLater, "every client of this tile has gone"));
    return true;
  }

  /// Under the lock: the waiters of `flight`, unregistering it; none when it is no longer
  /// the flight of `key` (already answered). This is what makes every answer happen once.
  std::vector<Callback> takeWaiters(const std::string& key, const std::shared_ptr<Flight>& flight) {
    const auto found = flights.find(key);
    if (found == flights.end() || found->second != flight) {
      return {};
    }
    flights.erase(found);
    return std::move(flight->waiters);
  }

  /// Under the lock: caches `tile` as the most recently used, then evicts down to the bound.
  /// A tile larger than the whole cache is not kept.
  void insert(const std::string& key, std::shared_ptr<const CachedTile> tile) {
    const std::size_t bytes = TileCache::chargedBytes(key, *tile);
    if (bytes > maxBytes) {
      return;
    }
    if (const auto found = index.find(key); found != index.end()) {
      removeEntry(found->second);
    }
    lru.push_front(Entry{key, std::move(tile), bytes});
    index.emplace(lru.front().key, lru.begin());
    counters.bytes += bytes;
    while (counters.bytes > maxBytes) {
      removeEntry(std::prev(lru.end()));
      ++counters.evictions;
    }
  }

  void removeEntry(std::list<Entry>::iterator entry) {
    counters.bytes -= entry->bytes;
    index.erase(entry->key);
    lru.erase(entry);
  }

  /// Records the outcome of `flight` and answers its waiters outside the lock. Rethrows the
  /// first exception a callback threw, after every waiter has been called.
  void finish(const std::string& key, const std::shared_ptr<Flight>& flight,
              const Outcome& outcome) {
    std::vector<Callback> waiters;
    {
      std::lock_guard lock(mutex);
      ++counters.computations;
      if (outcome.status == TileStatus::kOk) {
        insert(key, outcome.tile);
      } else {
        ++counters.errors;
      }
      waiters = takeWaiters(key, flight);
    }
    if (const std::exception_ptr error = deliver(waiters, outcome)) {
      std::rethrow_exception(error);
    }
  }

  /// Answers the waiters of a flight that will never run with kRetryLater. Callback exceptions are
  /// dropped: this runs from destructors and refusal paths with nobody to report them to.
  void abandon(const std::string& key, const std::shared_ptr<Flight>& flight) noexcept {
    std::vector<Callback> waiters;
    {
      std::lock_guard lock(mutex);
      waiters = takeWaiters(key, flight);
      counters.refused += waiters.size();
    }
    (void)deliver(waiters, errorOutcome(TileStatus::kRetryLater, "server busy"));
  }
};

/// One scheduled computation. Whatever becomes of the work — run, refused, or dropped unrun
/// by a pool that shuts down — the waiters of its flight are answered exactly once.
class Ticket {
public:
  Ticket(std::shared_ptr<CacheCore> core, std::string key, std::shared_ptr<Flight> flight,
         TileCache::Compute compute)
      : core_(std::move(core)), key_(std::move(key)), flight_(std::move(flight)),
        compute_(std::move(compute)) {}
  Ticket(const Ticket&) = delete;
  Ticket& operator=(const Ticket&) = delete;
  ~Ticket() {
    if (!ran_.load()) {
      core_->abandon(key_, flight_);
    }
  }

  /// Computes the tile and answers the waiters; only the first call does anything.
  void run() {
    if (ran_.exchange(true) || core_->cancelIfNobodyWaits(key_, flight_)) {
      return;
    }
    core_->finish(key_, flight_, computeSafely(compute_));
  }

  /// Answers the waiters with kRetryLater unless the computation already ran.
  void refuse() {
    if (!ran_.exchange(true)) {
      core_->abandon(key_, flight_);
    }
  }

private:
  std::shared_ptr<CacheCore> core_;
  std::string key_;
  std::shared_ptr<Flight> flight_;
  TileCache::Compute compute_;
  std::atomic<bool> ran_{false};
};

/// Hands the computation of a new flight to `schedule`; answers kRetryLater when it is refused.
void startFlight(const std::shared_ptr<CacheCore>& core, const std::string& key,
                 std::shared_ptr<Flight> flight, const TileCache::Compute& compute,
                 const TileCache::Schedule& schedule) {
  auto ticket = std::make_shared<Ticket>(core, key, std::move(flight), compute);
  bool queued = false;
  try {
    queued = schedule([ticket] { ticket->run(); });
  } catch (...) {
    queued = false; // A scheduler that throws refuses.
  }
  if (!queued) {
    ticket->refuse();
  }
}

} // namespace

struct TileCache::Impl {
  std::shared_ptr<CacheCore> core;
};

std::size_t TileCache::entryOverheadBytes() noexcept {
  // The tile and its shared_ptr control block (one make_shared allocation), the LRU list node,
  // the index node (next, key, iterator, cached hash) and its bucket slot.
  constexpr std::size_t kSharedControlBlock = 16, kListLinks = 2 * sizeof(void*);
  constexpr std::size_t kIndexNode =
      sizeof(void*) + sizeof(std::string_view) + sizeof(void*) + sizeof(std::size_t);
  return mallocChunk(sizeof(CachedTile) + kSharedControlBlock) +
         mallocChunk(sizeof(Entry) + kListLinks) + mallocChunk(kIndexNode) + sizeof(void*);
}

std::size_t TileCache::chargedBytes(const std::string& key, const CachedTile& tile) noexcept {
  return heapBytes(key) + heapBytes(tile.bytes) + heapBytes(tile.mimeType) + heapBytes(tile.etag) +
         heapBytes(tile.contentEncoding) + heapBytes(tile.vary) + heapBytes(tile.httpFields) +
         entryOverheadBytes();
}

TileCache::TileCache(std::size_t maxBytes)
    : impl_(std::make_unique<Impl>(Impl{std::make_shared<CacheCore>(maxBytes)})) {}

TileCache::~TileCache() = default;

void TileCache::get(const std::string& key, const Compute& compute, const Schedule& schedule,
                    Callback callback, Gone gone) {
  CacheCore& core = *impl_->core;
  std::shared_ptr<const CachedTile> hit;
  std::shared_ptr<Flight> started;
  {
    std::lock_guard lock(core.mutex);
    hit = core.lookup(key);
    if (!hit) {
      started = core.join(key, std::move(callback), std::move(gone));
    }
  }
  if (hit) {
    callback(Outcome{std::move(hit), TileStatus::kOk, {}});
  } else if (started) {
    startFlight(impl_->core, key, std::move(started), compute, schedule);
  }
}

std::shared_ptr<const CachedTile> TileCache::find(std::string_view key) {
  CacheCore& core = *impl_->core;
  std::lock_guard lock(core.mutex);
  return core.lookup(key);
}

TileCacheStats TileCache::stats() const {
  const CacheCore& core = *impl_->core;
  std::lock_guard lock(core.mutex);
  TileCacheStats result = core.counters;
  result.entries = core.lru.size();
  result.inFlight = core.flights.size();
  return result;
}

std::size_t TileCache::maxBytes() const noexcept {
  return impl_->core->maxBytes;
}

} // namespace strahler::service
