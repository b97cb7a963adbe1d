// The seed's response curves and density D = C_S · (C_I + C_H) / 2 (vegetation_density.h).
#include "strahler/input/params.h"
#include "strahler/layers/vegetation_density.h"

#include <gtest/gtest.h>

namespace strahler::layers {
namespace {

TEST(ResponseCurve, IsATrapezoidBetweenZeroAndOne) {
  const ResponseCurve c{1.0, 2.0, 3.0, 5.0};
  EXPECT_EQ(c(0.5), 0.0);
  EXPECT_DOUBLE_EQ(c(1.5), 0.5);
  EXPECT_EQ(c(2.5), 1.0);
  EXPECT_DOUBLE_EQ(c(4.0), 0.5);
  EXPECT_EQ(c(6.0), 0.0);
  const ResponseCurve step{0.0, 0.0, 1.0, 1.0};
  EXPECT_EQ(step(0.0), 1.0);
  EXPECT_EQ(step(1.0), 1.0);
}

TEST(VegetationDensity, FollowsTheSeedsProductAndIsZeroOnWater) {
  const Species& tree = kSpecies[static_cast<std::size_t>(speciesIndex("tree"))];
  // Deep soil, open sky, wet: C_S = C_I = C_H = 1, D = 1.
  EXPECT_DOUBLE_EQ(vegetationDensity(tree, {2.0, 1.0, 1.0, false}), 1.0);
  EXPECT_EQ(vegetationDensity(tree, {2.0, 1.0, 1.0, true}), 0.0);
  // No soil: C_S = 0 whatever the light and water (the seed's critical values).
  EXPECT_EQ(vegetationDensity(tree, {0.0, 1.0, 1.0, false}), 0.0);
  // Dry ground: D = C_S · C_I / 2.
  EXPECT_DOUBLE_EQ(vegetationDensity(tree, {2.0, 1.0, 0.0, false}), 0.5);
  EXPECT_EQ(speciesIndex("oak"), -1);
}

TEST(VegetationDensity, BushesKeepOffWetGroundWhereTreesThrive) {
  const Species& tree = kSpecies[static_cast<std::size_t>(speciesIndex("tree"))];
  const Species& bush = kSpecies[static_cast<std::size_t>(speciesIndex("bush"))];
  const Environment wetValley{1.5, 0.7, 1.0, false}, dryCrest{0.4, 1.0, 0.05, false};
  EXPECT_GT(vegetationDensity(tree, wetValley), vegetationDensity(bush, wetValley));
  EXPECT_GT(vegetationDensity(bush, dryCrest), vegetationDensity(tree, dryCrest));
}

TEST(VegetationDensity, AWorldsParamsReplaceTheCurvesOfTheSpeciesTheyName) {
  input::Params params;
  EXPECT_EQ(speciesOf(params, 0).sediment.rise0, kSpecies[0].sediment.rise0);
  params.vegetation["bush"] = {{1, 2, 3, 4}, {0, 0.5, 1, 1}, {0, 0.1, 0.2, 0.3}};
  const Species bush = speciesOf(params, static_cast<std::size_t>(speciesIndex("bush")));
  EXPECT_EQ(bush.name, "bush");
  EXPECT_EQ(bush.sediment.rise0, 1.0);
  EXPECT_EQ(bush.sediment.fall0, 4.0);
  EXPECT_EQ(bush.humidity.fall1, 0.2);
  // The tree keeps its defaults.
  EXPECT_EQ(speciesOf(params, 0).humidity.rise1, kSpecies[0].humidity.rise1);
  // params.json's species are core/layers' species.
  for (const char* name : input::kVegetationSpecies)
    EXPECT_GE(speciesIndex(name), 0) << name;
  EXPECT_EQ(std::size(input::kVegetationSpecies), kSpecies.size());
}

TEST(VegetationDensity, GridsAreThePointwiseDensity) {
  const Species& bush = kSpecies[1];
  const std::vector<double> s{0.0, 0.5, 1.0}, i{1.0, 0.95, 0.8}, h{0.2, 0.3, 0.95};
  const std::vector<std::uint8_t> w{0, 0, 255};
  const std::vector<double> d = vegetationDensity(bush, s, i, h, w);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_EQ(d[k], vegetationDensity(bush, {s[k], i[k], h[k], w[k] != 0}));
}

} // namespace
} // namespace strahler::layers
