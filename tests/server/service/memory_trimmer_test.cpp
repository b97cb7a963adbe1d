#include "memory_trimmer.h"

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace strahler::service {
namespace {

/// Under AddressSanitizer the heap is the sanitizer's allocator (freed blocks wait in its
/// quarantine), which malloc_trim does not shrink: there the tests check when trims happen, not
/// what they give back.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kGlibcHeap = false;
#else
constexpr bool kGlibcHeap = true;
#endif

/// VmRSS of this process in KB.
long residentKb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0)
      return std::stol(line.substr(6));
  return -1;
}

TEST(MemoryTrimmer, GivesFreedHeapBackAfterActivityOnly) {
  MemoryTrimmer trimmer(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(trimmer.trims(), 0u) << "trimmed without activity";
  // 64 MB in 64 KB blocks (below the mmap threshold: heap), written so they are resident; all
  // but the last freed, which pins the heap's top so free() alone cannot shrink it.
  std::vector<std::unique_ptr<char[]>> blocks;
  for (int i = 0; i < 1024; ++i) {
    blocks.emplace_back(new char[64 * 1024]);
    std::fill_n(blocks.back().get(), 64 * 1024, static_cast<char>(i));
  }
  for (std::size_t i = 0; i + 1 < blocks.size(); ++i)
    blocks[i].reset();
  const long held = residentKb();
  trimmer.noteActivity();
  for (int i = 0; i < 200 && trimmer.trims() == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(trimmer.trims(), 1u);
  if (kGlibcHeap) {
    EXPECT_LT(residentKb(), held - 32 * 1024) << "RSS " << held << " KB before the trim";
  }
  // One more trim a period later (what the activity freed after noting it), then none.
  for (int i = 0; i < 200 && trimmer.trims() < 2; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(trimmer.trims(), 2u) << "no trailing trim";
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(trimmer.trims(), 2u) << "trimmed again without new activity";
}

TEST(MemoryTrimmer, ZeroPeriodNeverTrims) {
  MemoryTrimmer trimmer(std::chrono::milliseconds(0));
  trimmer.noteActivity();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(trimmer.trims(), 0u);
}

} // namespace
} // namespace strahler::service
