#include "cache_test_support.h"
#include "tile_cache.h"
#include "watchdog.h"
#include "worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace strahler::service {
namespace {

constexpr int kThreads = 8;
constexpr int kRequestsPerThread = 2000;
constexpr int kKeys = 200;
constexpr std::size_t kCacheBytes = 8 * 1024;

/// The tile of key `k<index>`: its size and content follow from the key, so that a tile
/// delivered to the wrong request is detected.
std::shared_ptr<const CachedTile> tileOfKey(int index) {
  auto tile = std::make_shared<CachedTile>();
  tile->bytes = std::string(static_cast<std::size_t>(50 + index * 3), 'a');
  tile->etag = "\"k" + std::to_string(index) + "\"";
  return tile;
}

/// What the stress test checks after the storm: one answer per request, right tiles.
struct StressTally {
  std::vector<std::atomic<int>> answers =
      std::vector<std::atomic<int>>(kThreads * kRequestsPerThread);
  std::atomic<int> wrongTiles{0};
  std::atomic<int> unexpectedErrors{0};
  std::atomic<int> busy{0};
  std::atomic<int> boundViolations{0};
};

TEST(TileCacheStress, EveryRequestIsAnsweredExactlyOnceWithinTheByteBound) {
  test_support::Watchdog watchdog("tile cache stress", std::chrono::seconds(60));
  TileCache cache(kCacheBytes);
  StressTally tally;
  {
    WorkerPool pool(2, 64);
    const TileCache::Schedule schedule = [&](std::function<void()> work) {
      return pool.submit(std::move(work));
    };
    std::vector<std::jthread> clients;
    for (int t = 0; t < kThreads; ++t) {
      clients.emplace_back([&, t] {
        std::mt19937 random(static_cast<unsigned>(t + 1));
        std::uniform_int_distribution<int> keyOf(0, kKeys - 1);
        for (int i = 0; i < kRequestsPerThread; ++i) {
          const int index = keyOf(random);
          const int request = t * kRequestsPerThread + i;
          const std::string expectedEtag = "\"k" + std::to_string(index) + "\"";
          cache.get(
              "k" + std::to_string(index),
              [index] {
                std::this_thread::yield();
                return TileCache::Outcome{tileOfKey(index), TileStatus::kOk, {}};
              },
              schedule,
              [&tally, request, expectedEtag](const TileCache::Outcome& outcome) {
                ++tally.answers[static_cast<std::size_t>(request)];
                if (outcome.status == TileStatus::kRetryLater) {
                  ++tally.busy;
                } else if (outcome.status != TileStatus::kOk) {
                  ++tally.unexpectedErrors;
                } else if (outcome.tile->etag != expectedEtag) {
                  ++tally.wrongTiles;
                }
              });
          if (cache.stats().bytes > kCacheBytes) {
            ++tally.boundViolations;
          }
        }
      });
    }
    clients.clear();
    pool.drain();
  }
  int lost = 0;
  int duplicated = 0;
  for (const std::atomic<int>& answers : tally.answers) {
    lost += answers.load() == 0 ? 1 : 0;
    duplicated += answers.load() > 1 ? 1 : 0;
  }
  EXPECT_EQ(lost, 0);
  EXPECT_EQ(duplicated, 0);
  EXPECT_EQ(tally.wrongTiles.load(), 0);
  EXPECT_EQ(tally.unexpectedErrors.load(), 0);
  EXPECT_EQ(tally.boundViolations.load(), 0);

  const TileCacheStats stats = cache.stats();
  EXPECT_LE(stats.bytes, kCacheBytes);
  EXPECT_EQ(stats.inFlight, 0u);
  EXPECT_EQ(stats.hits + stats.misses, static_cast<std::size_t>(kThreads * kRequestsPerThread));
  EXPECT_EQ(stats.refused, static_cast<std::size_t>(tally.busy.load()));
  EXPECT_GT(stats.evictions, 0u) << "the cache must be small enough to churn";
  RecordProperty("hits", static_cast<int>(stats.hits));
  RecordProperty("coalesced", static_cast<int>(stats.coalesced));
  RecordProperty("refused", static_cast<int>(stats.refused));
  RecordProperty("evictions", static_cast<int>(stats.evictions));
}

} // namespace
} // namespace strahler::service
