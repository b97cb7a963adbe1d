#include "strahler/tiling/candidate_filters.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace strahler::tiling {
namespace {

using geometry::Aabb;
using geometry::Vec2;
using simd::InstructionSet;

/// The instruction sets this CPU has.
std::vector<InstructionSet> availableSets() {
  std::vector<InstructionSet> sets;
  const InstructionSet saved = simd::instructionSet();
  for (const InstructionSet set :
       {InstructionSet::kBaseline, InstructionSet::kAvx2, InstructionSet::kAvx512})
    if (simd::useInstructionSet(set))
      sets.push_back(set);
  simd::useInstructionSet(saved);
  return sets;
}

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

TEST(CandidateFilters, KeysEveryInstructionSetKeepsExactlyTheIdsWithinInOrder) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> key(-10.0f, 10.0f);
  for (const InstructionSet set : availableSets()) {
    // Every length around the vector widths, with keys on both ends of the range.
    for (std::size_t size = 0; size <= 70; ++size) {
      std::vector<float> keys(size);
      std::vector<std::uint32_t> ids(size);
      for (std::size_t k = 0; k < size; ++k) {
        keys[k] = k % 7 == 3 ? -2.5f : k % 11 == 5 ? 4.0f : key(rng);
        ids[k] = static_cast<std::uint32_t>(rng());
      }
      std::vector<std::uint32_t> out(size + kFilterOverrun, 0xdeadbeef);
      const std::size_t n = keepKeysWithin(keys, ids.data(), -2.5f, 4.0f, out.data(), set);
      out.resize(n);
      EXPECT_EQ(out, expectedIds(keys, ids, -2.5f, 4.0f))
          << "size " << size << ", instruction set " << static_cast<int>(set);
    }
  }
}

TEST(CandidateFilters, KeysEmptyRangeKeepsNothingAndWideRangeKeepsAll) {
  const std::vector<float> keys{1.0f,  -3.0f, 2.0f,  8.0f,  0.5f,  -1.0f, 6.0f,  7.0f, 9.0f,
                                10.0f, 11.0f, 12.0f, 13.0f, 14.0f, 15.0f, 16.0f, 17.0f};
  std::vector<std::uint32_t> ids(keys.size());
  for (std::size_t k = 0; k < ids.size(); ++k)
    ids[k] = static_cast<std::uint32_t>(100 + k);
  std::vector<std::uint32_t> out(keys.size() + kFilterOverrun);
  EXPECT_EQ(keepKeysWithin(keys, ids.data(), 5.0f, 4.0f, out.data()), 0u);
  ASSERT_EQ(keepKeysWithin(keys, ids.data(), -100.0f, 100.0f, out.data()), keys.size());
  out.resize(keys.size());
  EXPECT_EQ(out, ids);
}

TEST(CandidateFilters, DiscsMeetingABoxAreKeptInOrderOnEveryInstructionSet) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-3000.0, 3000.0), radius(0.0, 900.0);
  std::vector<primitives::TerrainPrimitive> terrain(300);
  for (primitives::TerrainPrimitive& t : terrain) {
    t.center = {coordinate(rng), coordinate(rng)};
    t.radius = radius(rng);
  }
  terrain[40].center = {1000.0, 250.0}; // on the box's corner and edges
  terrain[41].center = {-500.0, 0.0};
  terrain[42].center = {1500.0, 250.0};
  terrain[42].radius = 500.0;
  const TerrainDiscs discs(terrain);
  const std::vector<Aabb> boxes{{{-500.0, -250.0}, {1000.0, 250.0}}, {{0.0, 0.0}, {0.0, 0.0}}, {}};
  for (const InstructionSet set : availableSets())
    for (const Aabb& box : boxes)
      for (const std::uint32_t first : {0u, 3u, 40u})
        for (std::size_t count = 0; count <= 70; count += count < 20 ? 1 : 7) {
          std::vector<std::uint32_t> expected;
          for (std::uint32_t i = first; i < first + count; ++i)
            if (squaredDistanceToBox(discs.center(i), box) <= discs.reach2[i])
              expected.push_back(i);
          std::vector<std::uint32_t> ids(count + kFilterOverrun);
          std::vector<float> keys(count + kFilterOverrun);
          const std::size_t n =
              keepDiscsMeeting(discs, first, count, box, ids.data(), keys.data(), set);
          ids.resize(n);
          keys.resize(n);
          ASSERT_EQ(ids, expected) << "first " << first << ", count " << count
                                   << ", instruction set " << static_cast<int>(set);
          for (std::size_t k = 0; k < n; ++k)
            EXPECT_EQ(keys[k], static_cast<float>(terrain[ids[k]].center.y));
        }
}

TEST(CandidateFilters, DistanceToABoxIsZeroInsideAndInfiniteToAnEmptyBox) {
  const Aabb box{{0.0, 0.0}, {4.0, 2.0}};
  EXPECT_EQ(squaredDistanceToBox({1.0, 1.0}, box), 0.0);
  EXPECT_EQ(squaredDistanceToBox({7.0, 6.0}, box), 9.0 + 16.0);
  EXPECT_EQ(squaredDistanceToBox({-3.0, 1.0}, box), 9.0);
  EXPECT_EQ(squaredDistanceToBox({1.0, 1.0}, Aabb{}), std::numeric_limits<double>::infinity());
}

} // namespace
} // namespace strahler::tiling
