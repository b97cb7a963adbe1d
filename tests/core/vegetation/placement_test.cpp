#include "strahler/vegetation/placement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <thread>

namespace strahler::vegetation {
namespace {

using geometry::Aabb;
using geometry::Vec2;

constexpr std::uint64_t kSeed = 0x5EEDF00Dull;

/// A density that varies over tens of metres, from 0 to 1, the same whichever tile asks.
const FunctionDensity& wavyDensity() {
  static const FunctionDensity field([](std::size_t species, Vec2 p) {
    const double phase = static_cast<double>(species);
    return static_cast<float>(0.5 + 0.5 * std::sin(p.x / 37.0 + phase) * std::cos(p.y / 53.0));
  });
  return field;
}

std::vector<Instance> place(const Aabb& box, const DensityField& density,
                            SpeciesMask mask = kAllSpecies, PlacementRules rules = {}) {
  return placeInstances(kSeed, Footprint::box(box), density, mask, rules);
}

std::vector<Instance> unionOf(std::initializer_list<std::vector<Instance>> tiles) {
  std::vector<Instance> all;
  for (const auto& t : tiles)
    all.insert(all.end(), t.begin(), t.end());
  std::sort(all.begin(), all.end(), instanceLess);
  return all;
}

TEST(VegetationPlacement, AdjacentTilesUnionEqualsTheTileCoveringBoth) {
  const auto& d = wavyDensity();
  const auto west = place(Aabb{{-256, -40}, {0, 216}}, d);
  const auto east = place(Aabb{{0, -40}, {256, 216}}, d);
  const auto both = place(Aabb{{-256, -40}, {256, 216}}, d);
  ASSERT_GT(both.size(), 1000u);
  EXPECT_FALSE(west.empty());
  EXPECT_FALSE(east.empty());
  EXPECT_EQ(west.size() + east.size(), both.size());
  EXPECT_TRUE(unionOf({west, east}) == both); // every field bit for bit, same order
}

TEST(VegetationPlacement, FourQuadrantsUnionEqualsTheirParent) {
  const auto& d = wavyDensity();
  const double o = 1000.3; // off the species grids' cell corners
  std::vector<std::vector<Instance>> quads;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      quads.push_back(place(
          Aabb{{o + 128.0 * i, o + 128.0 * j}, {o + 128.0 * (i + 1), o + 128.0 * (j + 1)}}, d));
  const auto parent = place(Aabb{{o, o}, {o + 256.0, o + 256.0}}, d);
  EXPECT_TRUE(unionOf({quads[0], quads[1], quads[2], quads[3]}) == parent);
}

TEST(VegetationPlacement, SeamHoldsWithoutGrowthAndWithManyRounds) {
  const auto& d = wavyDensity();
  for (PlacementRules rules : {PlacementRules{1, 0}, PlacementRules{8, 8}}) {
    const auto a = place(Aabb{{0, 0}, {96, 96}}, d, kAllSpecies, rules);
    const auto b = place(Aabb{{0, 96}, {96, 192}}, d, kAllSpecies, rules);
    const auto ab = place(Aabb{{0, 0}, {96, 192}}, d, kAllSpecies, rules);
    EXPECT_TRUE(unionOf({a, b}) == ab) << rules.dartRounds << " rounds";
  }
}

TEST(VegetationPlacement, SameSpeciesKeepTheirSpacing) {
  const UniformDensity full({1.0f, 1.0f});
  const auto all = place(Aabb{{0, 0}, {120, 120}}, full, kAllSpecies, {4, 0});
  ASSERT_GT(all.size(), 1000u);
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      if (all[i].species == all[j].species) {
        ASSERT_GE(geometry::distance(all[i].position, all[j].position),
                  kSpecies[all[i].species].spacing)
            << i << ", " << j;
      }
}

TEST(VegetationPlacement, DensityZeroGivesNone) {
  const UniformDensity none({0.0f, 0.0f});
  EXPECT_TRUE(place(Aabb{{0, 0}, {256, 256}}, none).empty());
}

TEST(VegetationPlacement, DensityOneGivesTheDocumentedPacking) {
  // kPackingAtFullDensity (placement.h): individuals per spacing² at density 1, before growth.
  const UniformDensity full({1.0f, 1.0f});
  const double side = 400.0;
  const auto all = place(Aabb{{0, 0}, {side, side}}, full, kAllSpecies, {4, 0});
  for (std::size_t s = 0; s < kSpecies.size(); ++s) {
    const auto n =
        std::count_if(all.begin(), all.end(), [&](const Instance& i) { return i.species == s; });
    const double perCell =
        static_cast<double>(n) * kSpecies[s].spacing * kSpecies[s].spacing / (side * side);
    EXPECT_NEAR(perCell, kPackingAtFullDensity, kPackingTolerance) << kSpecies[s].name;
    EXPECT_LE(static_cast<std::size_t>(n), instanceBound(kSpecies[s], side, side));
  }
}

TEST(VegetationPlacement, HalfDensityPlacesFewer) {
  const auto full = place(Aabb{{0, 0}, {200, 200}}, UniformDensity({1.0f, 1.0f}), 1u, {4, 0});
  const auto half = place(Aabb{{0, 0}, {200, 200}}, UniformDensity({0.5f, 0.5f}), 1u, {4, 0});
  EXPECT_LT(half.size(), full.size() * 9 / 10);
  EXPECT_GT(half.size(), full.size() / 3);
}

TEST(VegetationPlacement, TreesDoNotDependOnWhetherBushesAreAsked) {
  const auto& d = wavyDensity();
  const Aabb box{{0, 0}, {200, 200}};
  auto both = place(box, d, kAllSpecies);
  std::erase_if(both, [](const Instance& i) { return i.species != 0; });
  EXPECT_FALSE(both.empty());
  EXPECT_TRUE(place(box, d, 1u) == both);
}

TEST(VegetationPlacement, GrowthThinsAndSizesThePlants) {
  const UniformDensity full({1.0f, 1.0f});
  const Aabb box{{0, 0}, {150, 150}};
  const auto seedlings = place(box, full, kAllSpecies, {4, 0});
  const auto grown = place(box, full, kAllSpecies, {4, 4});
  EXPECT_LT(grown.size(), seedlings.size());
  for (const Instance& i : grown) {
    EXPECT_GE(i.radius, static_cast<float>(kSpecies[i.species].startRadius));
    EXPECT_LE(i.radius, static_cast<float>(kSpecies[i.species].maxRadius));
    EXPECT_GE(i.scale, 0.8f);
    EXPECT_LT(i.scale, 1.2f);
    EXPECT_GE(i.rotation, 0.0f);
    EXPECT_LE(i.rotation, 6.2831855f);
  }
}

TEST(VegetationPlacement, SameOutputTwiceAndOnOtherThreads) {
  const auto& d = wavyDensity();
  const Aabb box{{-300, 500}, {-44, 756}};
  const auto first = place(box, d);
  EXPECT_TRUE(place(box, d) == first);
  std::vector<std::vector<Instance>> results(2);
  std::vector<std::thread> threads;
  for (auto& r : results)
    threads.emplace_back([&r, &box, &d] { r = place(box, d); });
  for (auto& t : threads)
    t.join();
  for (const auto& r : results)
    EXPECT_TRUE(r == first);
  EXPECT_FALSE(placeInstances(kSeed + 1, Footprint::box(box), d, kAllSpecies) == first);
}

TEST(VegetationPlacement, BorderGrowsWithTheRuleCounts) {
  EXPECT_DOUBLE_EQ(dependencyBorder({4, 4}, kAllSpecies, 0), 4 * 6.0 + 2 * 4 * 4.0);
  // Bushes among trees: the trees' radius reaches them, their own spacing bounds the darts.
  EXPECT_DOUBLE_EQ(dependencyBorder({4, 4}, kAllSpecies, 1), 4 * 6.0 + 2 * 4 * 2.0);
  EXPECT_DOUBLE_EQ(dependencyBorder({4, 4}, 2u, 1), 4 * 1.8 + 2 * 4 * 2.0);
  EXPECT_DOUBLE_EQ(dependencyBorder({0, 0}, kAllSpecies, 0), 0.0);
}

} // namespace
} // namespace strahler::vegetation
