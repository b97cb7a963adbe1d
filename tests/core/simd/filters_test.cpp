#include "strahler/simd/filters.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace strahler::simd {
namespace {

std::vector<InstructionSet> supportedSets() {
  std::vector<InstructionSet> sets;
  for (const InstructionSet set :
       {InstructionSet::kBaseline, InstructionSet::kAvx2, InstructionSet::kAvx512})
    if (supports(set))
      sets.push_back(set);
  return sets;
}

TEST(SimdFilters, KeepWithinKeepsTheSameIdsInOrderOnEverySet) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> key(-10.0f, 10.0f);
  for (const std::size_t size : {0u, 1u, 7u, 8u, 15u, 16u, 17u, 100u}) {
    std::vector<float> keys(size);
    std::vector<std::uint32_t> ids(size + kFilterOverrun);
    for (std::size_t k = 0; k < size; ++k) {
      keys[k] = key(rng);
      ids[k] = static_cast<std::uint32_t>(1000 + 3 * k);
    }
    std::vector<std::uint32_t> expected;
    for (std::size_t k = 0; k < size; ++k)
      if (keys[k] >= -2.0f && keys[k] <= 3.0f)
        expected.push_back(ids[k]);
    for (const InstructionSet set : supportedSets()) {
      std::vector<std::uint32_t> out(size + kFilterOverrun);
      out.resize(keepWithin(keys, ids.data(), -2.0f, 3.0f, out.data(), set));
      EXPECT_EQ(out, expected) << static_cast<int>(set) << " size " << size;
    }
  }
}

TEST(SimdFilters, KeepDiscsMeetingKeepsDiscsWithinReachOfTheBoxOnEverySet) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-100.0, 100.0), reach(0.0, 40.0);
  const std::size_t count = 61;
  std::vector<double> x(count + kFilterOverrun), y(count + kFilterOverrun),
      reach2(count + kFilterOverrun);
  std::vector<float> key(count + kFilterOverrun);
  for (std::size_t i = 0; i < count; ++i) {
    x[i] = coordinate(rng);
    y[i] = coordinate(rng);
    const double r = reach(rng);
    reach2[i] = r * r;
    key[i] = static_cast<float>(y[i]);
  }
  const DiscColumns discs{x.data(), y.data(), reach2.data(), key.data()};
  const Box box{-20.0, -10.0, 30.0, 25.0};
  for (const std::uint32_t first : {0u, 3u}) {
    std::vector<std::uint32_t> expected;
    for (std::uint32_t i = first; i < count; ++i) {
      const double gx = std::max({box.minX - x[i], x[i] - box.maxX, 0.0});
      const double gy = std::max({box.minY - y[i], y[i] - box.maxY, 0.0});
      if (gx * gx + gy * gy <= reach2[i])
        expected.push_back(i);
    }
    ASSERT_FALSE(expected.empty());
    ASSERT_LT(expected.size(), count - first);
    for (const InstructionSet set : supportedSets()) {
      std::vector<std::uint32_t> ids(count + kFilterOverrun);
      std::vector<float> keys(count + kFilterOverrun);
      const std::size_t n =
          keepDiscsMeeting(discs, first, count - first, box, ids.data(), keys.data(), set);
      ids.resize(n);
      EXPECT_EQ(ids, expected) << static_cast<int>(set);
      for (std::size_t k = 0; k < n; ++k)
        EXPECT_EQ(keys[k], key[ids[k]]);
    }
  }
}

} // namespace
} // namespace strahler::simd
