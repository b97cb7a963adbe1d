#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

namespace strahler::service {

/// Hands the heap memory glibc malloc keeps after bursts of tile computations back to the
/// system (malloc_trim): a thread wakes once per `period` and trims when noteActivity() was
/// called since its last wake, and once more at the wake after (what was freed after the last
/// activity was noted). Tile temporaries (a 1024² tile needs ~20 MB) otherwise stay in
/// the arenas: +90 MB of RSS after 64 such tiles, measured in docs/performance.md. At most one
/// trim per period, so its cost (milliseconds) never follows the request rate. It also fixes
/// glibc's mmap threshold at kMappedAllocationBytes, so a large tile's buffers are mapped and
/// unmapped whole instead of raising the dynamic threshold and fragmenting the heap, which
/// trimming cannot undo (+7..+55 MB after 24 tiles of 1024² without it, +2 MB with it).
/// Thread-safe.
class MemoryTrimmer {
public:
  /// Allocations of at least this size are mmapped (a 1024² float grid is 4 MiB; 512² tiles
  /// and smaller stay on the heap, where they are cheap).
  static constexpr int kMappedAllocationBytes = 4 << 20;

  /// Starts the thread and fixes the mmap threshold; a zero `period` disables both.
  explicit MemoryTrimmer(std::chrono::milliseconds period);
  ~MemoryTrimmer();
  MemoryTrimmer(const MemoryTrimmer&) = delete;
  MemoryTrimmer& operator=(const MemoryTrimmer&) = delete;

  /// Records that memory was allocated and freed (a tile computed): the next wake trims.
  void noteActivity() noexcept { active_.store(true, std::memory_order_relaxed); }
  /// Trims done so far.
  std::uint64_t trims() const noexcept { return trims_.load(std::memory_order_relaxed); }

private:
  void run();

  const std::chrono::milliseconds period_;
  std::atomic<bool> active_{false};
  std::atomic<std::uint64_t> trims_{0};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

} // namespace strahler::service
