#include "watchdog.h"
#include "worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <latch>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

namespace strahler::service {
namespace {

using test_support::Watchdog;

/// Drains `pool` on another thread while a task waits on `release`: drain must not return
/// before the release, which this function gives after a pause.
void drainWhileHeld(WorkerPool& pool, std::latch& release) {
  std::atomic<bool> drained{false};
  std::jthread drainer([&] {
    pool.drain();
    drained = true;
  });
  std::this_thread::sleep_for(
      std::chrono::milliseconds(20)); // Give drain a chance to return early.
  EXPECT_FALSE(drained.load());
  release.count_down();
  drainer.join();
}

TEST(WorkerPool, RunsTasksConcurrentlyOnItsThreads) {
  constexpr int kThreads = 4;
  Watchdog watchdog("tasks on 4 threads");
  WorkerPool pool(kThreads, 8);
  EXPECT_EQ(pool.threads(), kThreads);
  std::latch together(kThreads); // Only passes when all four tasks run at the same time.
  std::mutex idsMutex;
  std::set<std::thread::id> ids;
  for (int i = 0; i < kThreads; ++i) {
    ASSERT_TRUE(pool.submit([&] {
      together.arrive_and_wait();
      std::lock_guard lock(idsMutex);
      ids.insert(std::this_thread::get_id());
    }));
  }
  pool.drain();
  EXPECT_EQ(ids.size(), static_cast<std::size_t>(kThreads));
  EXPECT_EQ(ids.count(std::this_thread::get_id()), 0u);
}

TEST(WorkerPool, CancelQueuedDropsWaitingTasksAndLetsRunningOnesFinish) {
  Watchdog watchdog("cancel queued");
  WorkerPool pool(1, 8);
  std::latch started(1);
  std::latch release(1);
  std::atomic<int> ran{0};
  std::atomic<int> destroyedUnrun{0};
  /// Counts its destruction when it was never run (what the tile cache's ticket answers 503 on).
  struct Probe {
    explicit Probe(std::atomic<int>* counter) : destroyedUnrun(counter) {}
    Probe(const Probe&) = delete;
    Probe& operator=(const Probe&) = delete;
    std::atomic<int>* destroyedUnrun;
    bool ran = false;
    ~Probe() {
      if (!ran)
        ++*destroyedUnrun;
    }
  };
  ASSERT_TRUE(pool.submit([&] {
    started.count_down();
    release.wait();
    ++ran;
  }));
  started.wait();
  for (int i = 0; i < 5; ++i) {
    auto probe = std::make_shared<Probe>(&destroyedUnrun);
    ASSERT_TRUE(pool.submit([&, probe] {
      probe->ran = true;
      ++ran;
    }));
  }
  EXPECT_EQ(pool.cancelQueued(), 5u);
  EXPECT_EQ(destroyedUnrun.load(), 5);
  EXPECT_EQ(pool.queued(), 0u);
  EXPECT_EQ(pool.running(), 1u);
  EXPECT_FALSE(pool.submit([] {})) << "a cancelled pool takes no new task";
  drainWhileHeld(pool, release);
  EXPECT_EQ(ran.load(), 1);
}

TEST(WorkerPool, RefusesTasksBeyondTheQueueCap) {
  Watchdog watchdog("queue cap");
  WorkerPool pool(2, 3);
  std::latch started(2);
  std::latch release(1);
  std::atomic<int> ran{0};
  const auto blocked = [&] {
    if (ran.fetch_add(1) < 2) {
      started.count_down();
    }
    release.wait();
  };
  // Two tasks for the two workers plus three waiting: whether or not the workers have
  // picked theirs up yet, the sixth does not fit.
  for (int i = 0; i < 5; ++i) {
    EXPECT_TRUE(pool.submit(blocked)) << "task " << i;
  }
  EXPECT_FALSE(pool.submit(blocked));
  started.wait();
  EXPECT_EQ(pool.running(), 2u);
  EXPECT_EQ(pool.queued(), 3u);
  EXPECT_FALSE(pool.submit(blocked));
  release.count_down();
  pool.drain();
  EXPECT_EQ(ran.load(), 5);
}

TEST(WorkerPool, QueuedAndRunningReportTheBacklog) {
  Watchdog watchdog("backlog counters");
  WorkerPool pool(1, 4);
  std::latch started(1);
  std::latch release(1);
  ASSERT_TRUE(pool.submit([&] {
    started.count_down();
    release.wait();
  }));
  started.wait();
  ASSERT_TRUE(pool.submit([] {}));
  ASSERT_TRUE(pool.submit([] {}));
  EXPECT_EQ(pool.running(), 1u);
  EXPECT_EQ(pool.queued(), 2u);
  release.count_down();
  pool.drain();
  EXPECT_EQ(pool.running(), 0u);
  EXPECT_EQ(pool.queued(), 0u);
}

TEST(WorkerPool, DrainWaitsForQueuedAndRunningTasks) {
  Watchdog watchdog("drain");
  WorkerPool pool(1, 10);
  std::latch started(1);
  std::latch release(1);
  std::atomic<int> finished{0};
  ASSERT_TRUE(pool.submit([&] {
    started.count_down();
    release.wait();
    ++finished;
  }));
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(pool.submit([&] { ++finished; }));
  }
  started.wait();
  drainWhileHeld(pool, release);
  EXPECT_EQ(finished.load(), 6);
}

TEST(WorkerPool, DrainWaitsForTheRunningTaskWhenNothingIsQueued) {
  Watchdog watchdog("drain of a running task");
  WorkerPool pool(1, 10);
  std::latch started(1);
  std::latch release(1);
  std::atomic<bool> finished{false};
  ASSERT_TRUE(pool.submit([&] {
    started.count_down();
    release.wait();
    finished = true;
  }));
  started.wait();
  drainWhileHeld(pool, release);
  EXPECT_TRUE(finished.load());
}

TEST(WorkerPool, RefusesTasksAfterDrain) {
  WorkerPool pool(1, 4);
  pool.drain();
  std::atomic<bool> ran{false};
  EXPECT_FALSE(pool.submit([&] { ran = true; }));
  EXPECT_FALSE(ran.load());
}

TEST(WorkerPool, RefusesAnEmptyTask) {
  WorkerPool pool(1, 4);
  EXPECT_FALSE(pool.submit(nullptr));
}

TEST(WorkerPool, ThrowingTaskDoesNotKillItsWorker) {
  Watchdog watchdog("throwing task");
  WorkerPool pool(1, 4);
  std::atomic<bool> ran{false};
  ASSERT_TRUE(pool.submit([] { throw std::runtime_error("task failed"); }));
  ASSERT_TRUE(pool.submit([] { throw 7; }));
  ASSERT_TRUE(pool.submit([&] { ran = true; }));
  pool.drain();
  EXPECT_TRUE(ran.load()) << "the only worker must survive the throwing tasks";
  EXPECT_EQ(pool.failures(), 2u);
}

/// Counts down `latch` when destroyed: tells when a task was dropped.
struct DestructionSignal {
  explicit DestructionSignal(std::latch& latch) : latch_(&latch) {}
  DestructionSignal(const DestructionSignal&) = delete;
  DestructionSignal& operator=(const DestructionSignal&) = delete;
  ~DestructionSignal() { latch_->count_down(); }
  std::latch* latch_;
};

TEST(WorkerPool, DestructorFinishesRunningTasksAndDropsQueuedOnes) {
  Watchdog watchdog("destructor");
  auto pool = std::make_unique<WorkerPool>(1, 4);
  std::latch started(1);
  std::latch release(1);
  std::latch dropped(2);
  std::atomic<bool> runningFinished{false};
  std::atomic<int> queuedRan{0};
  ASSERT_TRUE(pool->submit([&] {
    started.count_down();
    release.wait();
    runningFinished = true;
  }));
  started.wait();
  for (int i = 0; i < 2; ++i) {
    auto signal = std::make_shared<DestructionSignal>(dropped);
    ASSERT_TRUE(pool->submit([&queuedRan, signal] { ++queuedRan; }));
  }
  std::jthread destroyer([&] { pool.reset(); });
  dropped.wait(); // The queued tasks are destroyed while the running one is still blocked.
  release.count_down();
  destroyer.join();
  EXPECT_TRUE(runningFinished.load());
  EXPECT_EQ(queuedRan.load(), 0);
}

TEST(WorkerPool, NonPositiveThreadCountMeansOneThread) {
  Watchdog watchdog("one thread");
  WorkerPool pool(0, 1);
  EXPECT_EQ(pool.threads(), 1);
  std::atomic<bool> ran{false};
  ASSERT_TRUE(pool.submit([&] { ran = true; }));
  pool.drain();
  EXPECT_TRUE(ran.load());
}

} // namespace
} // namespace strahler::service
