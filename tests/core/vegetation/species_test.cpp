#include "strahler/vegetation/species.h"

#include <gtest/gtest.h>

namespace strahler::vegetation {
namespace {

TEST(VegetationSpecies, TableHoldsTreesAndBushesWithSaneConstants) {
  ASSERT_GE(kSpecies.size(), 2u);
  EXPECT_EQ(kSpecies[0].name, "tree");
  EXPECT_EQ(kSpecies[1].name, "bush");
  for (const Species& s : kSpecies) {
    SCOPED_TRACE(std::string(s.name));
    EXPECT_GT(s.spacing, 0.0);
    EXPECT_GT(s.startRadius, 0.0);
    EXPECT_GT(s.growth, 0.0);
    EXPECT_GE(s.maxRadius, s.startRadius);
    EXPECT_GT(s.maxAge, 0);
    EXPECT_LE(s.minZoom, kMaxVegetationZoom);
    EXPECT_EQ(s.radiusAt(0), s.startRadius);
    EXPECT_EQ(s.radiusAt(1'000'000), s.maxRadius);
  }
  EXPECT_GT(kSpecies[0].spacing, kSpecies[1].spacing);
}

TEST(VegetationSpecies, TableIsInCanopyOrder) {
  // A later species can never outgrow an earlier one, so it never kills it (placement.h).
  for (std::size_t i = 0; i < kSpecies.size(); ++i)
    for (std::size_t j = i + 1; j < kSpecies.size(); ++j)
      EXPECT_GT(kSpecies[i].startRadius, kSpecies[j].maxRadius) << i << " vs " << j;
}

TEST(VegetationSpecies, VisibleZoomsFollowMinZoom) {
  EXPECT_EQ(visibleSpecies(0), 0u);
  EXPECT_EQ(visibleSpecies(15), 0u);
  EXPECT_EQ(visibleSpecies(16), 1u);
  EXPECT_EQ(visibleSpecies(17), kAllSpecies);
  EXPECT_EQ(visibleSpecies(kMaxVegetationZoom), kAllSpecies);
  EXPECT_EQ(visibleSpecies(kMaxVegetationZoom + 1), 0u);
}

TEST(VegetationSpecies, EveryServedTileStaysUnderTheInstanceCap) {
  for (int z = 0; z <= kMaxVegetationZoom + 1; ++z) {
    const std::size_t bound = maxInstancesPerWebTile(z, visibleSpecies(z));
    EXPECT_LE(bound, kMaxInstancesPerTile) << "zoom " << z;
    if (visibleSpecies(z) != 0) {
      EXPECT_GT(bound, 0u);
    }
  }
  // One zoom shallower than a species' minZoom would break the cap: minZoom is not lax.
  EXPECT_GT(maxInstancesPerWebTile(kSpecies[1].minZoom - 1, kAllSpecies), kMaxInstancesPerTile);
}

TEST(VegetationSpecies, InstanceBoundIsTheDiskPackingBound) {
  const Species& tree = kSpecies[0];
  const double s = tree.spacing;
  const double expected = (100.0 + s) * (50.0 + s) / (3.14159265358979 * s * s / 4.0);
  EXPECT_EQ(instanceBound(tree, 100.0, 50.0), static_cast<std::size_t>(expected));
}

} // namespace
} // namespace strahler::vegetation
