#include "worker_pool.h"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace strahler::service {

struct WorkerPool::Impl {
  std::size_t threadCount;
  std::size_t maxQueued;
  mutable std::mutex mutex;
  std::condition_variable workAvailable; ///< A task was queued, or the pool shuts down.
  std::condition_variable idle;          ///< Queue empty and nothing running.
  std::deque<std::function<void()>> queue;
  std::size_t runningCount = 0;
  std::size_t failureCount = 0;
  bool accepting = true; ///< False after drain() or in the destructor.
  bool shutdown = false; ///< Workers exit; set only by the destructor.
  std::vector<std::thread> workers;

  Impl(int threads, std::size_t maxQueuedTasks)
      : threadCount(static_cast<std::size_t>(std::max(threads, 1))), maxQueued(maxQueuedTasks) {}

  /// Takes the next task, or nothing when the pool shuts down. Marks the task as running.
  std::function<void()> takeTask() {
    std::unique_lock lock(mutex);
    workAvailable.wait(lock, [&] { return shutdown || !queue.empty(); });
    if (shutdown) {
      return {};
    }
    std::function<void()> task = std::move(queue.front());
    queue.pop_front();
    ++runningCount;
    return task;
  }

  /// Runs `task` and destroys it before the pool counts it as finished, so that drain()
  /// also waits for whatever the task's captures do on destruction.
  void runTask(std::function<void()> task) {
    bool failed = false;
    try {
      task();
    } catch (...) {
      failed = true; // A throwing task must not take its worker down.
    }
    task = nullptr;
    std::lock_guard lock(mutex);
    --runningCount;
    failureCount += failed ? 1 : 0;
    if (runningCount == 0 && queue.empty()) {
      idle.notify_all();
    }
  }

  void workerLoop() {
    while (std::function<void()> task = takeTask()) {
      runTask(std::move(task));
    }
  }

  /// Refuses new tasks, drops the queued ones, lets the running ones finish, joins.
  void stopAndJoin() {
    std::deque<std::function<void()>> dropped;
    {
      std::lock_guard lock(mutex);
      accepting = false;
      shutdown = true;
      dropped.swap(queue);
    }
    workAvailable.notify_all();
    dropped.clear(); // Outside the lock: a dropped task's captures may call back into the pool.
    for (std::thread& worker : workers) {
      worker.join();
    }
  }
};

WorkerPool::WorkerPool(int threads, std::size_t maxQueued)
    : impl_(std::make_unique<Impl>(threads, maxQueued)) {
  impl_->workers.reserve(impl_->threadCount);
  try {
    for (std::size_t i = 0; i < impl_->threadCount; ++i) {
      impl_->workers.emplace_back([impl = impl_.get()] { impl->workerLoop(); });
    }
  } catch (...) {
    impl_->stopAndJoin(); // No destructor runs for a half-built pool.
    throw;
  }
}

WorkerPool::~WorkerPool() {
  impl_->stopAndJoin();
}

bool WorkerPool::submit(std::function<void()> task) {
  if (!task) {
    return false;
  }
  {
    std::lock_guard lock(impl_->mutex);
    // Tasks picked up by idle workers do not wait, so idle workers add to the capacity.
    const std::size_t idleWorkers = impl_->threadCount - impl_->runningCount;
    if (!impl_->accepting || impl_->queue.size() >= impl_->maxQueued + idleWorkers) {
      return false;
    }
    impl_->queue.push_back(std::move(task));
  }
  impl_->workAvailable.notify_one();
  return true;
}

std::size_t WorkerPool::queued() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->queue.size();
}

std::size_t WorkerPool::running() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->runningCount;
}

std::size_t WorkerPool::failures() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->failureCount;
}

int WorkerPool::threads() const noexcept {
  return static_cast<int>(impl_->threadCount);
}

void WorkerPool::drain() {
  std::unique_lock lock(impl_->mutex);
  impl_->accepting = false;
  impl_->idle.wait(lock, [&] { return impl_->queue.empty() && impl_->runningCount == 0; });
}

std::size_t WorkerPool::cancelQueued() {
  std::deque<std::function<void()>> dropped;
  {
    std::lock_guard lock(impl_->mutex);
    impl_->accepting = false;
    dropped.swap(impl_->queue);
    if (impl_->runningCount == 0) {
      impl_->idle.notify_all();
    }
  }
  const std::size_t count = dropped.size();
  dropped.clear(); // Outside the lock: a dropped task's captures may call back into the pool.
  return count;
}

} // namespace strahler::service
