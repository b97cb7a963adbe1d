#include "memory_trimmer.h"

#include <malloc.h>

namespace strahler::service {

MemoryTrimmer::MemoryTrimmer(std::chrono::milliseconds period) : period_(period) {
  if (period_.count() <= 0)
    return;
  mallopt(M_MMAP_THRESHOLD, kMappedAllocationBytes);
  thread_ = std::thread([this] { run(); });
}

MemoryTrimmer::~MemoryTrimmer() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable())
    thread_.join();
}

void MemoryTrimmer::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  // A tile's last temporaries can be freed after its activity was noted (its response still
  // being written), and a burst's last trim can come before that: one more trim a period
  // after the activity stops gives those back too.
  bool trailing = false;
  while (!wake_.wait_for(lock, period_, [this] { return stopping_; })) {
    const bool active = active_.exchange(false, std::memory_order_relaxed);
    if (!active && !trailing)
      continue;
    trailing = active;
    lock.unlock();
    malloc_trim(0);
    trims_.fetch_add(1, std::memory_order_relaxed);
    lock.lock();
  }
}

} // namespace strahler::service
