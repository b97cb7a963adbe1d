#pragma once

#include <cstddef>
#include <functional>
#include <memory>

namespace strahler::service {

/// A fixed set of worker threads with a bounded queue, separate from the I/O threads.
class WorkerPool {
public:
  /// `threads` workers (at least 1); at most `maxQueued` tasks waiting (beyond those running).
  /// A task that an idle worker takes at once does not count as waiting.
  WorkerPool(int threads, std::size_t maxQueued);
  /// Finishes the running tasks, drops the queued ones, joins the workers.
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Queues `task`; false (task not run) when the queue is full or the pool is stopping.
  bool submit(std::function<void()> task);
  /// Tasks waiting now.
  std::size_t queued() const;
  /// Tasks running now.
  std::size_t running() const;
  /// Tasks that ended with an exception so far (caught; the worker lives on).
  std::size_t failures() const;
  /// Number of worker threads.
  int threads() const noexcept;
  /// Stops taking tasks, waits for queued and running tasks to finish. Not from a task of
  /// this pool (it would wait for itself).
  void drain();
  /// Stops taking tasks and destroys the queued ones unrun, on the calling thread (a task's
  /// captures answer its requester on destruction); running tasks go on. Returns at once;
  /// drain() then waits only for the running ones. For shutdown: nobody would get the rest.
  /// Returns the number of tasks dropped.
  std::size_t cancelQueued();

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace strahler::service
