#include "strahler/vegetation/placement.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace strahler::vegetation {
namespace {

constexpr SpeciesIndex kTree = 0;
constexpr SpeciesIndex kBush = 1;

TEST(VegetationGrowth, TheLargerOfTwoClosePlantsKillsTheSmaller) {
  // After one step: radii radiusAt(21) = 6 m and radiusAt(1) = 2.25 m, 3 m apart.
  std::vector<Plant> plants{{{0.0, 0.0}, kTree, 20, true}, {{3.0, 0.0}, kTree, 0, true}};
  simulateGrowth(plants, 1);
  EXPECT_TRUE(plants[0].alive);
  EXPECT_FALSE(plants[1].alive);
  EXPECT_EQ(plants[0].age, 21);
}

TEST(VegetationGrowth, PlantsOutsideTheLargerRadiusBothLive) {
  std::vector<Plant> plants{{{0.0, 0.0}, kTree, 20, true}, {{6.5, 0.0}, kTree, 0, true}};
  simulateGrowth(plants, 1);
  EXPECT_TRUE(plants[0].alive);
  EXPECT_TRUE(plants[1].alive);
}

TEST(VegetationGrowth, EqualRadiiBothLive) {
  std::vector<Plant> plants{{{0.0, 0.0}, kTree, 30, true}, {{1.0, 0.0}, kTree, 25, true}};
  simulateGrowth(plants, 1);
  EXPECT_TRUE(plants[0].alive); // both at the 6 m cap
  EXPECT_TRUE(plants[1].alive);
}

TEST(VegetationGrowth, TreesShadeBushesButBushesNeverKillTrees) {
  std::vector<Plant> plants{{{0.0, 0.0}, kBush, 19, true}, {{1.0, 0.0}, kTree, 0, true}};
  simulateGrowth(plants, 1);
  EXPECT_FALSE(plants[0].alive);
  EXPECT_TRUE(plants[1].alive);
}

TEST(VegetationGrowth, OldAgeKills) {
  const int maxAge = kSpecies[kTree].maxAge;
  std::vector<Plant> plants{{{0.0, 0.0}, kTree, maxAge - 1, true},
                            {{100.0, 0.0}, kTree, maxAge, true}};
  simulateGrowth(plants, 1);
  EXPECT_TRUE(plants[0].alive);
  EXPECT_FALSE(plants[1].alive);
  simulateGrowth(plants, 1);
  EXPECT_FALSE(plants[0].alive);
}

TEST(VegetationGrowth, KillsAreSimultaneous) {
  // a (6 m) kills b (4.25 m) 4 m away; b would have killed c (2.25 m) 3 m further, and does,
  // as b was alive at the start of the competition.
  std::vector<Plant> plants{
      {{0.0, 0.0}, kTree, 20, true}, {{4.0, 0.0}, kTree, 8, true}, {{7.0, 0.0}, kTree, 0, true}};
  simulateGrowth(plants, 1);
  EXPECT_TRUE(plants[0].alive);
  EXPECT_FALSE(plants[1].alive);
  EXPECT_FALSE(plants[2].alive);
}

TEST(VegetationGrowth, ResultDoesNotDependOnOrder) {
  std::vector<Plant> plants;
  for (int i = 0; i < 200; ++i)
    plants.push_back({{(i * 37 % 101) * 0.9, (i * 53 % 97) * 0.7},
                      static_cast<SpeciesIndex>(i % 2),
                      i % 19,
                      true});
  std::vector<Plant> reversed(plants.rbegin(), plants.rend());
  simulateGrowth(plants, 3);
  simulateGrowth(reversed, 3);
  std::reverse(reversed.begin(), reversed.end());
  int alive = 0;
  for (std::size_t i = 0; i < plants.size(); ++i) {
    EXPECT_EQ(plants[i].alive, reversed[i].alive) << i;
    alive += plants[i].alive;
  }
  EXPECT_GT(alive, 0);
  EXPECT_LT(alive, 200);
}

} // namespace
} // namespace strahler::vegetation
