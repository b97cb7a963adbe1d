#include "cache_test_support.h"
#include "tile_cache.h"
#include "watchdog.h"
#include "worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <latch>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

namespace strahler::service {
namespace {

using test_support::computeReturning;
using test_support::entryCharge;
using test_support::makeTile;
using test_support::ManualScheduler;
using test_support::OutcomeLog;
using test_support::runInline;
using test_support::Watchdog;

/// Fetches `key` (computed inline as a tile of `size` bytes); returns the delivered tile.
std::shared_ptr<const CachedTile> fetch(TileCache& cache, const std::string& key,
                                        std::size_t size = 100, int* computeCalls = nullptr) {
  std::shared_ptr<const CachedTile> delivered;
  cache.get(
      key,
      [&] {
        if (computeCalls != nullptr) {
          ++*computeCalls;
        }
        return TileCache::Outcome{makeTile(size), TileStatus::kOk, {}};
      },
      runInline, [&](const TileCache::Outcome& outcome) { delivered = outcome.tile; });
  return delivered;
}

TEST(TileCache, FirstRequestMissesAndComputesThenRepeatHitsWithSameTile) {
  TileCache cache(10000);
  int calls = 0;
  const auto first = fetch(cache, "a", 100, &calls);
  const auto second = fetch(cache, "a", 100, &calls);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(second, first);
  EXPECT_EQ(calls, 1);
  const TileCacheStats stats = cache.stats();
  EXPECT_EQ(stats.misses, 1u);
  EXPECT_EQ(stats.hits, 1u);
  EXPECT_EQ(stats.computations, 1u);
  EXPECT_EQ(stats.entries, 1u);
  EXPECT_EQ(stats.inFlight, 0u);
}

TEST(TileCache, ChargesKeyTileMimeEtagAndFixedOverheadPerEntry) {
  TileCache cache(10000);
  auto tile = std::make_shared<CachedTile>();
  tile->bytes.assign(300, 'x');
  tile->mimeType = "image/png";
  tile->etag = "\"abc\"";
  cache.get("key-1", computeReturning(tile), runInline, [](const TileCache::Outcome&) {});
  // Short strings live inside the object; a heap string costs its capacity + NUL + header.
  EXPECT_EQ(cache.stats().bytes, 320u + TileCache::entryOverheadBytes());
  EXPECT_EQ(cache.stats().bytes, TileCache::chargedBytes("key-1", *tile));
}

TEST(TileCache, ChargesTheCapacityAStringHoldsNotItsSize) {
  auto reserved = std::make_shared<CachedTile>();
  reserved->bytes.reserve(50'000); // an encoder's reservation, never shrunk
  reserved->bytes.assign(1'500, 'x');
  auto exact = std::make_shared<CachedTile>(*reserved);
  exact->bytes.shrink_to_fit();
  EXPECT_GE(TileCache::chargedBytes("k", *reserved), 50'000u);
  EXPECT_LT(TileCache::chargedBytes("k", *exact), 1'600u + TileCache::entryOverheadBytes());
  // So a cache bound holds as many tiles as it can really afford.
  TileCache cache(200'000);
  for (int i = 0; i < 10; ++i)
    cache.get("k" + std::to_string(i), computeReturning(reserved), runInline,
              [](const TileCache::Outcome&) {});
  EXPECT_LE(cache.stats().entries, 3u);
  EXPECT_LE(cache.stats().bytes, 200'000u);
}

TEST(TileCache, ChargesPreparedHttpFieldsToo) {
  TileCache cache(10000);
  auto tile = std::make_shared<CachedTile>();
  tile->bytes.assign(300, 'x');
  tile->httpFields = "ETag: \"abc\"\r\n";
  cache.get("key-1", computeReturning(tile), runInline, [](const TileCache::Outcome&) {});
  EXPECT_EQ(cache.stats().bytes, 320u + TileCache::entryOverheadBytes()); // fields are short
  EXPECT_EQ(cache.stats().bytes, TileCache::chargedBytes("key-1", *tile));
  tile->httpFields.assign(100, 'f');
  EXPECT_EQ(TileCache::chargedBytes("key-1", *tile), 320u + 112u + TileCache::entryOverheadBytes());
}

TEST(TileCache, FindReturnsCachedTilesAsHitsAndCountsNothingOtherwise) {
  TileCache cache(10000);
  EXPECT_EQ(cache.find("a"), nullptr);
  EXPECT_EQ(cache.stats().hits + cache.stats().misses, 0u);
  const auto stored = fetch(cache, "a");
  EXPECT_EQ(cache.find("a"), stored);
  EXPECT_EQ(cache.find("b"), nullptr);
  const TileCacheStats stats = cache.stats();
  EXPECT_EQ(stats.hits, 1u);
  EXPECT_EQ(stats.misses, 1u);
  EXPECT_EQ(stats.computations, 1u);
}

TEST(TileCache, FindRefreshesRecency) {
  const std::size_t entry = entryCharge("a", 100);
  TileCache cache(2 * entry);
  fetch(cache, "a");
  fetch(cache, "b");
  ASSERT_NE(cache.find("a"), nullptr); // a is now more recent than b
  fetch(cache, "c");                   // evicts b
  EXPECT_NE(cache.find("a"), nullptr);
  EXPECT_EQ(cache.find("b"), nullptr);
  EXPECT_NE(cache.find("c"), nullptr);
}

TEST(TileCache, EvictsLeastRecentlyUsedFirst) {
  const std::size_t entry = entryCharge("a", 100);
  TileCache cache(3 * entry);
  fetch(cache, "a");
  fetch(cache, "b");
  fetch(cache, "c");
  fetch(cache, "a"); // a is now more recent than b and c.
  fetch(cache, "d"); // Evicts b, the least recently used.
  EXPECT_EQ(cache.stats().evictions, 1u);
  EXPECT_EQ(cache.stats().bytes, 3 * entry);

  int calls = 0;
  for (const char* key : {"a", "c", "d"}) {
    fetch(cache, key, 100, &calls);
  }
  EXPECT_EQ(calls, 0) << "a, c and d must still be cached";
  fetch(cache, "b", 100, &calls);
  EXPECT_EQ(calls, 1) << "b must have been evicted";
}

TEST(TileCache, BytesNeverExceedTheBoundOverManyInserts) {
  const std::size_t bound = 4096;
  TileCache cache(bound);
  std::mt19937 random(7);
  std::uniform_int_distribution<std::size_t> sizeOf(0, 1500);
  std::uniform_int_distribution<int> keyOf(0, 99);
  for (int i = 0; i < 2000; ++i) {
    fetch(cache, "k" + std::to_string(keyOf(random)), sizeOf(random));
    const TileCacheStats stats = cache.stats();
    ASSERT_LE(stats.bytes, bound) << "after insert " << i;
    ASSERT_LE(stats.entries * TileCache::entryOverheadBytes(), stats.bytes);
  }
  EXPECT_GT(cache.stats().evictions, 100u);
}

TEST(TileCache, TileLargerThanTheCacheIsDeliveredButNotCached) {
  TileCache cache(1000);
  fetch(cache, "small", 100);
  int calls = 0;
  const auto big = fetch(cache, "big", 5000, &calls);
  ASSERT_NE(big, nullptr);
  EXPECT_EQ(big->bytes.size(), 5000u);
  fetch(cache, "big", 5000, &calls);
  EXPECT_EQ(calls, 2);
  const TileCacheStats stats = cache.stats();
  EXPECT_EQ(stats.entries, 1u) << "the small tile must not be evicted for an uncacheable one";
  EXPECT_EQ(stats.evictions, 0u);
}

TEST(TileCache, ConcurrentRequestsForOneKeyComputeOnceAndShareTheTile) {
  OutcomeLog log;
  constexpr int kThreads = 32;
  Watchdog watchdog("single flight", std::chrono::seconds(20));
  TileCache cache(1 << 20);
  std::latch requested(kThreads);
  std::latch release(1);
  std::atomic<int> computeCalls{0};
  const auto tile = makeTile(256);
  const TileCache::Compute compute = [&] {
    ++computeCalls;
    release.wait(); // Hold the computation until every request has joined it.
    return TileCache::Outcome{tile, TileStatus::kOk, {}};
  };
  std::vector<std::jthread> computing;
  std::mutex computingMutex;
  const TileCache::Schedule schedule = [&](std::function<void()> work) {
    std::lock_guard lock(computingMutex);
    computing.emplace_back(std::move(work));
    return true;
  };
  {
    std::vector<std::jthread> requesters;
    for (int i = 0; i < kThreads; ++i) {
      requesters.emplace_back([&] {
        cache.get("same", compute, schedule, log.callback());
        requested.count_down();
      });
    }
    requested.wait();
    EXPECT_EQ(cache.stats().inFlight, 1u);
    release.count_down();
  }
  ASSERT_TRUE(log.waitFor(kThreads));
  computing.clear();
  EXPECT_EQ(computeCalls.load(), 1);
  const auto outcomes = log.outcomes();
  ASSERT_EQ(outcomes.size(), static_cast<std::size_t>(kThreads));
  for (const auto& outcome : outcomes) {
    EXPECT_EQ(outcome.status, TileStatus::kOk);
    EXPECT_EQ(outcome.tile, tile);
  }
  const TileCacheStats stats = cache.stats();
  EXPECT_EQ(stats.coalesced, static_cast<std::size_t>(kThreads - 1));
  EXPECT_EQ(stats.misses, static_cast<std::size_t>(kThreads));
  EXPECT_EQ(stats.computations, 1u);
  EXPECT_EQ(stats.inFlight, 0u);
}

TEST(TileCache, ErrorsReachEveryWaiterAndAreNotCached) {
  OutcomeLog log;
  TileCache cache(10000);
  ManualScheduler scheduler;
  const TileCache::Compute failing = [] {
    return TileCache::Outcome{nullptr, TileStatus::kNotFound, "no tile"};
  };
  for (int i = 0; i < 3; ++i) {
    cache.get("k", failing, scheduler.schedule(), log.callback());
  }
  ASSERT_EQ(scheduler.pending(), 1u);
  scheduler.runNext();
  const auto outcomes = log.outcomes();
  ASSERT_EQ(outcomes.size(), 3u);
  for (const auto& outcome : outcomes) {
    EXPECT_EQ(outcome.status, TileStatus::kNotFound);
    EXPECT_EQ(outcome.message, "no tile");
    EXPECT_EQ(outcome.tile, nullptr);
  }
  EXPECT_EQ(cache.stats().entries, 0u);
  EXPECT_EQ(cache.stats().errors, 1u);
  cache.get("k", failing, scheduler.schedule(), log.callback());
  EXPECT_EQ(scheduler.pending(), 1u) << "an error must not be served from the cache";
}

TEST(TileCache, RefusedScheduleAnswersRetryLaterToEveryoneWhoJoinedMeanwhile) {
  OutcomeLog log;
  TileCache cache(10000);
  const auto compute = computeReturning(makeTile(10));
  int scheduleCalls = 0;
  // While the first request is being scheduled (no lock held), two more join its flight.
  const TileCache::Schedule refusing = [&](std::function<void()>) {
    if (++scheduleCalls == 1) {
      cache.get("k", compute, runInline, log.callback());
      cache.get("k", compute, runInline, log.callback());
    }
    return false;
  };
  cache.get("k", compute, refusing, log.callback());
  const auto outcomes = log.outcomes();
  ASSERT_EQ(outcomes.size(), 3u);
  for (const auto& outcome : outcomes) {
    EXPECT_EQ(outcome.status, TileStatus::kRetryLater);
    EXPECT_EQ(outcome.message, "server busy");
  }
  EXPECT_EQ(scheduleCalls, 1);
  EXPECT_EQ(cache.stats().inFlight, 0u);
  EXPECT_EQ(cache.stats().refused, 3u);
  EXPECT_EQ(cache.stats().coalesced, 2u);

  // The refused flight is gone: the next request starts a fresh one.
  cache.get("k", compute, runInline, log.callback());
  ASSERT_EQ(log.outcomes().size(), 4u);
  EXPECT_EQ(log.outcomes().back().status, TileStatus::kOk);
}

TEST(TileCache, ScheduleThatThrowsCountsAsRefusal) {
  OutcomeLog log;
  TileCache cache(10000);
  const TileCache::Schedule throwing = [](std::function<void()>) -> bool {
    throw std::runtime_error("queue broken");
  };
  cache.get("k", computeReturning(makeTile(10)), throwing, log.callback());
  ASSERT_EQ(log.outcomes().size(), 1u);
  EXPECT_EQ(log.outcomes()[0].status, TileStatus::kRetryLater);
  EXPECT_EQ(cache.stats().inFlight, 0u);
}

TEST(TileCache, WorkDroppedUnrunAnswersRetryLaterOnce) {
  OutcomeLog log;
  TileCache cache(10000);
  ManualScheduler scheduler;
  const auto compute = computeReturning(makeTile(10));
  cache.get("k", compute, scheduler.schedule(), log.callback());
  cache.get("k", compute, scheduler.schedule(), log.callback());
  EXPECT_TRUE(log.outcomes().empty());
  scheduler.dropAll();
  const auto outcomes = log.outcomes();
  ASSERT_EQ(outcomes.size(), 2u);
  EXPECT_EQ(outcomes[0].status, TileStatus::kRetryLater);
  EXPECT_EQ(outcomes[1].status, TileStatus::kRetryLater);
  EXPECT_EQ(cache.stats().inFlight, 0u);
}

TEST(TileCache, QueuedWorkWhoseRequestersAllLeftIsNotComputed) {
  OutcomeLog log;
  TileCache cache(10000);
  ManualScheduler scheduler;
  int calls = 0;
  const TileCache::Compute compute = [&] {
    ++calls;
    return TileCache::Outcome{makeTile(10), TileStatus::kOk, {}};
  };
  auto first = std::make_shared<std::atomic<bool>>(false);
  auto second = std::make_shared<std::atomic<bool>>(false);
  cache.get("gone", compute, scheduler.schedule(), log.callback(), first);
  cache.get("gone", compute, scheduler.schedule(), log.callback(), second);
  cache.get("half", compute, scheduler.schedule(), log.callback(), first);
  cache.get("half", compute, scheduler.schedule(), log.callback(), nullptr); // never gone
  *first = true;
  *second = true;
  scheduler.runNext(); // "gone": both requesters left before a worker took it
  EXPECT_EQ(calls, 0);
  scheduler.runNext(); // "half": one is still there
  EXPECT_EQ(calls, 1);
  const auto outcomes = log.outcomes();
  ASSERT_EQ(outcomes.size(), 4u);
  EXPECT_EQ(outcomes[0].status, TileStatus::kRetryLater);
  EXPECT_EQ(outcomes[1].status, TileStatus::kRetryLater);
  EXPECT_NE(outcomes[2].tile, nullptr);
  EXPECT_NE(outcomes[3].tile, nullptr);
  const TileCacheStats stats = cache.stats();
  EXPECT_EQ(stats.cancelled, 1u);
  EXPECT_EQ(stats.computations, 1u);
  EXPECT_EQ(stats.inFlight, 0u);
  const int callsBefore = calls;
  const auto again = fetch(cache, "gone", 10, &calls);
  ASSERT_NE(again, nullptr) << "a cancelled key is computed for the next request";
  EXPECT_EQ(calls, callsBefore + 1);
  EXPECT_EQ(fetch(cache, "gone", 10, &calls), again) << "and then served from the cache";
  EXPECT_EQ(calls, callsBefore + 1);
}

TEST(TileCache, WorkDroppedByADestroyedPoolAnswersRetryLater) {
  OutcomeLog log;
  Watchdog watchdog("pool destroyed with queued tile work");
  TileCache cache(10000);
  std::latch started(1);
  std::latch release(1);
  auto pool = std::make_unique<WorkerPool>(1, 4);
  ASSERT_TRUE(pool->submit([&] {
    started.count_down();
    release.wait();
  }));
  started.wait();
  cache.get(
      "k", computeReturning(makeTile(10)),
      [&](std::function<void()> work) { return pool->submit(std::move(work)); }, log.callback());
  std::jthread destroyer([&] { pool.reset(); });
  // The destructor drops the queued tile work while the worker is still busy.
  ASSERT_TRUE(log.waitFor(1));
  release.count_down();
  destroyer.join();
  const auto outcomes = log.outcomes();
  ASSERT_EQ(outcomes.size(), 1u);
  EXPECT_EQ(outcomes[0].status, TileStatus::kRetryLater);
  EXPECT_EQ(cache.stats().inFlight, 0u);
}

TEST(TileCache, ComputeThatThrowsFailsEveryWaiter) {
  OutcomeLog log;
  TileCache cache(10000);
  ManualScheduler scheduler;
  const TileCache::Compute throwing = []() -> TileCache::Outcome {
    throw std::runtime_error("boom");
  };
  cache.get("k", throwing, scheduler.schedule(), log.callback());
  cache.get("k", throwing, scheduler.schedule(), log.callback());
  scheduler.runNext();
  const auto outcomes = log.outcomes();
  ASSERT_EQ(outcomes.size(), 2u);
  for (const auto& outcome : outcomes) {
    EXPECT_EQ(outcome.status, TileStatus::kFailed);
    EXPECT_NE(outcome.message.find("boom"), std::string::npos);
  }
  EXPECT_EQ(cache.stats().entries, 0u);

  cache.get(
      "k", []() -> TileCache::Outcome { throw 42; }, runInline, log.callback());
  ASSERT_EQ(log.outcomes().size(), 3u);
  EXPECT_EQ(log.outcomes()[2].status, TileStatus::kFailed);
}

TEST(TileCache, SuccessWithoutTileIsAFailure) {
  OutcomeLog log;
  TileCache cache(10000);
  cache.get(
      "k", [] { return TileCache::Outcome{}; }, runInline, log.callback());
  ASSERT_EQ(log.outcomes().size(), 1u);
  EXPECT_EQ(log.outcomes()[0].status, TileStatus::kFailed);
  EXPECT_EQ(cache.stats().entries, 0u);
}

TEST(TileCache, ThrowingCallbackDoesNotStopTheOtherWaiters) {
  OutcomeLog log;
  TileCache cache(10000);
  ManualScheduler scheduler;
  const auto compute = computeReturning(makeTile(10));
  cache.get("k", compute, scheduler.schedule(), log.callback());
  cache.get("k", compute, scheduler.schedule(),
            [](const TileCache::Outcome&) { throw std::runtime_error("callback failed"); });
  cache.get("k", compute, scheduler.schedule(), log.callback());
  EXPECT_THROW(scheduler.runNext(), std::runtime_error);
  EXPECT_EQ(log.outcomes().size(), 2u);
  EXPECT_EQ(cache.stats().entries, 1u);
}

TEST(TileCache, CallbacksRunOutsideTheCacheLock) {
  Watchdog watchdog("re-entrant callbacks", std::chrono::seconds(10));
  TileCache cache(10000);
  ManualScheduler scheduler;
  int reentered = 0;
  // A callback that uses the cache again would deadlock if it ran under the cache lock.
  const TileCache::Callback reentrant = [&](const TileCache::Outcome& outcome) {
    EXPECT_EQ(outcome.status, TileStatus::kOk);
    EXPECT_GE(cache.stats().misses, 1u);
    cache.get("other", computeReturning(makeTile(5)), runInline,
              [&](const TileCache::Outcome&) { ++reentered; });
  };
  cache.get("k", computeReturning(makeTile(10)), scheduler.schedule(), reentrant);
  cache.get("k", computeReturning(makeTile(10)), scheduler.schedule(), reentrant);
  scheduler.runNext(); // Miss path: both waiters answered by the computation.
  cache.get("k", computeReturning(makeTile(10)), scheduler.schedule(), reentrant); // Hit path.
  EXPECT_EQ(reentered, 3);
}

TEST(TileCache, ComputationMayOutliveTheCache) {
  OutcomeLog log;
  ManualScheduler scheduler;
  {
    TileCache cache(10000);
    cache.get("k", computeReturning(makeTile(10)), scheduler.schedule(), log.callback());
  }
  scheduler.runNext();
  ASSERT_EQ(log.outcomes().size(), 1u);
  EXPECT_EQ(log.outcomes()[0].status, TileStatus::kOk);
}

} // namespace
} // namespace strahler::service
