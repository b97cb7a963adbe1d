#include "strahler/construction/operators.h"
#include "strahler/primitives/terrain_primitive.h"

#include <gtest/gtest.h>

namespace strahler::construction {
namespace {

TEST(Operators, BlendFollowsThePaper) {
  // h = (10·0.5 + 20·0.25) / 0.75 = 13.333…, w = 0.75 / 2.
  const Sample s = blend({10.0, 0.5}, {20.0, 0.25});
  EXPECT_DOUBLE_EQ(s.h, 10.0 / 0.75);
  EXPECT_DOUBLE_EQ(s.w, 0.375);
  EXPECT_EQ(blend({5.0, 0.0}, {7.0, 0.0}).w, 0.0);
}

TEST(Operators, BlendOfManyIsTheWeightedMean) {
  // Σ h w = 1·1 + 2·1 + 6·2 = 15, Σ w = 4: h = 3.75, w = 4/3.
  const Sample s = blendSums(15.0, 4.0, 3);
  EXPECT_DOUBLE_EQ(s.h, 3.75);
  EXPECT_DOUBLE_EQ(s.w, 4.0 / 3.0);
  // Pairwise B for two children is the same thing.
  const Sample pair = blend({1.0, 1.0}, {6.0, 2.0});
  const Sample sums = blendSums(1.0 + 12.0, 3.0, 2);
  EXPECT_DOUBLE_EQ(pair.h, sums.h);
  EXPECT_DOUBLE_EQ(pair.w, sums.w);
}

TEST(Operators, ReplaceFollowsThePaper) {
  // h = (1 − 0.25)·100 + 0.25·40 = 85, w = 0.0625 + 0.75·0.8 = 0.6625.
  const Sample s = replace({100.0, 0.8}, {40.0, 0.25});
  EXPECT_DOUBLE_EQ(s.h, 85.0);
  EXPECT_DOUBLE_EQ(s.w, 0.6625);
  // Full influence replaces entirely; none leaves A alone.
  EXPECT_DOUBLE_EQ(replace({100.0, 0.3}, {40.0, 1.0}).h, 40.0);
  EXPECT_DOUBLE_EQ(replace({100.0, 0.3}, {40.0, 0.0}).h, 100.0);
}

TEST(Operators, UnionFollowsThePaper) {
  const Sample s = unite({3.0, 0.9}, {5.0, 0.1});
  EXPECT_DOUBLE_EQ(s.h, 5.0);
  EXPECT_DOUBLE_EQ(s.w, 0.9);
}

TEST(Operators, UnionByInfluenceTakesTheDominantSample) {
  EXPECT_DOUBLE_EQ(uniteByInfluence({3.0, 0.9}, {5.0, 0.1}).h, 3.0);
  EXPECT_DOUBLE_EQ(uniteByInfluence({3.0, 0.2}, {5.0, 0.7}).h, 5.0);
  EXPECT_DOUBLE_EQ(uniteByInfluence({3.0, 0.5}, {2.0, 0.5}).h, 2.0);
}

TEST(Falloff, HasCompactSupport) {
  EXPECT_DOUBLE_EQ(primitives::falloff(0.0, 100.0), 1.0);
  EXPECT_DOUBLE_EQ(primitives::falloff(25.0, 100.0), 0.75 * 0.75);
  EXPECT_EQ(primitives::falloff(100.0, 100.0), 0.0);
  EXPECT_EQ(primitives::falloff(1e9, 100.0), 0.0);
}

} // namespace
} // namespace strahler::construction
