#include "strahler/tiling/key_filter.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace strahler::tiling {
namespace {

using construction::InstructionSet;

/// The ids keepKeysWithin() must keep, by the plain definition.
std::vector<std::uint32_t> expectedIds(const std::vector<float>& keys,
                                       const std::vector<std::uint32_t>& ids, float low,
                                       float high) {
  std::vector<std::uint32_t> kept;
  for (std::size_t k = 0; k < keys.size(); ++k)
    if (keys[k] >= low && keys[k] <= high)
      kept.push_back(ids[k]);
  return kept;
}

TEST(KeyFilter, EveryInstructionSetKeepsExactlyTheIdsWithinInOrder) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> key(-10.0f, 10.0f);
  for (const InstructionSet set :
       {InstructionSet::kBaseline, InstructionSet::kAvx2, InstructionSet::kAvx512}) {
    const InstructionSet saved = construction::instructionSet();
    const bool available = construction::useInstructionSet(set);
    construction::useInstructionSet(saved);
    if (!available)
      continue; // this CPU lacks it
    // Every length around the vector widths, with keys on both ends of the range.
    for (std::size_t size = 0; size <= 70; ++size) {
      std::vector<float> keys(size);
      std::vector<std::uint32_t> ids(size);
      for (std::size_t k = 0; k < size; ++k) {
        keys[k] = k % 7 == 3 ? -2.5f : k % 11 == 5 ? 4.0f : key(rng);
        ids[k] = static_cast<std::uint32_t>(rng());
      }
      std::vector<std::uint32_t> out(size + kKeyFilterOverrun, 0xdeadbeef);
      const std::size_t n = keepKeysWithin(keys, ids.data(), -2.5f, 4.0f, out.data(), set);
      out.resize(n);
      EXPECT_EQ(out, expectedIds(keys, ids, -2.5f, 4.0f))
          << "size " << size << ", instruction set " << static_cast<int>(set);
    }
  }
}

TEST(KeyFilter, EmptyRangeKeepsNothingAndWideRangeKeepsAll) {
  const std::vector<float> keys{1.0f,  -3.0f, 2.0f,  8.0f,  0.5f,  -1.0f, 6.0f,  7.0f, 9.0f,
                                10.0f, 11.0f, 12.0f, 13.0f, 14.0f, 15.0f, 16.0f, 17.0f};
  std::vector<std::uint32_t> ids(keys.size());
  for (std::size_t k = 0; k < ids.size(); ++k)
    ids[k] = static_cast<std::uint32_t>(100 + k);
  std::vector<std::uint32_t> out(keys.size() + kKeyFilterOverrun);
  EXPECT_EQ(keepKeysWithin(keys, ids.data(), 5.0f, 4.0f, out.data()), 0u);
  ASSERT_EQ(keepKeysWithin(keys, ids.data(), -100.0f, 100.0f, out.data()), keys.size());
  out.resize(keys.size());
  EXPECT_EQ(out, ids);
}

} // namespace
} // namespace strahler::tiling
