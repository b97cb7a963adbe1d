#include "memory_trimmer.h"

#include <malloc.h>

namespace strahler::service {

MemoryTrimmer::MemoryTrimmer(std::chrono::milliseconds period) : period_(period) {
  if (period_.count() > 0)
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
  while (!wake_.wait_for(lock, period_, [this] { return stopping_; })) {
    if (!active_.exchange(false, std::memory_order_relaxed))
      continue;
    lock.unlock();
    malloc_trim(0);
    trims_.fetch_add(1, std::memory_order_relaxed);
    lock.lock();
  }
}

} // namespace strahler::service
