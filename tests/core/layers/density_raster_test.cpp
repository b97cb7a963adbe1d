// The vegetation layer's one-pass raster against the layer functions it stands for: the same
// doubles at every pixel (with water, sea, soil-less crests and skipped sky views in the tile),
// and the even-pixel sky view with and without its mask.
#include "upsample.h"

#include "strahler/layers/density_raster.h"
#include "strahler/layers/humidity.h"
#include "strahler/layers/sediment.h"
#include "strahler/layers/sky_view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace strahler::layers {
namespace {

constexpr int kSize = 48, kBorder = SkyView::kReach + 1;

/// Steep rolling hills dipping under the sea in the south-west, m, at global pixel indices.
double terrain(int x, int y) {
  return 30.0 * std::sin(x * 0.19) * std::cos(y * 0.13) + 6.0 * std::sin((x + 2 * y) * 0.41) +
         0.8 * (x + y) - 25.0;
}

struct Tile {
  std::vector<double> heights, spacing;
  BorderedHeights grid;
  Tile() {
    for (int y = -kBorder; y < kSize + kBorder; ++y)
      for (int x = -kBorder; x < kSize + kBorder; ++x)
        heights.push_back(terrain(x, y));
    for (int y = -kBorder; y < kSize + kBorder; ++y)
      spacing.push_back(9.0 + 0.01 * y); // rows of Web Mercator tiles differ in spacing
    grid = {heights, kSize, kSize, kBorder, spacing};
  }
};

TEST(VegetationDensityRaster, IsTheLayerFunctionsComposedExactly) {
  const Tile tile;
  const std::size_t cw = kSize / 2 + 1;
  std::vector<double> wetEven(cw * cw);
  for (std::size_t k = 0; k < wetEven.size(); ++k)
    wetEven[k] = k % 7 == 0 ? 0.0 : 0.5 + 0.5 * std::sin(0.3 * static_cast<double>(k));
  std::vector<std::uint8_t> water(kSize * kSize, 0);
  for (std::size_t k = 0; k < water.size(); k += 13)
    water[k] = 255;
  const std::vector<double> wetness = detail::upsampleEven(wetEven, kSize, kSize);
  for (const Species& species : kSpecies) {
    const std::vector<double> expected =
        vegetationDensity(species, sedimentThickness(tile.grid), skyView(tile.grid, 2),
                          humidity(tile.grid, wetness), water);
    const std::vector<double> got = vegetationDensityRaster(species, tile.grid, wetEven, water);
    ASSERT_EQ(got.size(), expected.size());
    int zeros = 0, growing = 0;
    for (std::size_t k = 0; k < got.size(); ++k) {
      ASSERT_EQ(got[k], expected[k]) << species.name << " at pixel " << k;
      zeros += got[k] == 0.0 ? 1 : 0;
      growing += got[k] > 0.1 ? 1 : 0;
    }
    // The tile holds both what the raster skips (no soil, water) and vegetation.
    EXPECT_GT(zeros, 100) << species.name << " " << growing;
    EXPECT_GT(growing, 100) << species.name;
  }
}

TEST(SkyViewEven, IsSkyViewAtTheEvenPixelsAndComputesOnlyTheFlaggedOnes) {
  const Tile tile;
  const std::size_t cw = kSize / 2 + 1;
  const std::vector<double> all = skyViewEven(tile.grid);
  const std::vector<double> fine = skyView(tile.grid, 2);
  for (std::size_t j = 0; j < cw - 1; ++j)
    for (std::size_t i = 0; i < cw - 1; ++i)
      ASSERT_EQ(all[j * cw + i], fine[2 * j * kSize + 2 * i]);
  std::vector<std::uint8_t> wanted(cw * cw, 0);
  for (std::size_t k = 0; k < wanted.size(); ++k)
    wanted[k] = (k / 3) % 2 == 0 ? 1 : 0; // runs of three
  const std::vector<double> some = skyViewEven(tile.grid, wanted);
  for (std::size_t k = 0; k < some.size(); ++k)
    ASSERT_EQ(some[k], wanted[k] != 0 ? all[k] : 1.0) << k;
}

TEST(SamplesInside, TakesEverySampleOrTheEvenOnesWithTheirRowsSpacing) {
  tiling::SampleGrid grid;
  grid.width = 8;
  grid.height = 6;
  for (int y = 0; y < grid.height; ++y) {
    grid.rowSpacing.push_back(10.0 + y);
    for (int x = 0; x < grid.width; ++x) {
      grid.points.push_back({1.0 * x, -1.0 * y});
      grid.bounds.add(grid.points.back());
    }
  }
  const tiling::SampleGrid inside = samplesInside(grid, 1, 1);
  ASSERT_EQ(inside.width, 6);
  ASSERT_EQ(inside.height, 4);
  EXPECT_EQ(inside.points.front().x, 1.0);
  EXPECT_EQ(inside.points.back().x, 6.0);
  EXPECT_EQ(inside.rowSpacing.front(), 11.0);
  const tiling::SampleGrid even = samplesInside(grid, 1, 2);
  ASSERT_EQ(even.width, 4); // 0, 2, 4 inside and the border's first
  ASSERT_EQ(even.height, 3);
  EXPECT_EQ(even.points[1].x, 3.0);
  EXPECT_EQ(even.points[static_cast<std::size_t>(even.width)].y, -3.0);
  EXPECT_EQ(even.rowSpacing[2], 15.0);
  EXPECT_EQ(even.bounds.max.x, 7.0);
}

} // namespace
} // namespace strahler::layers
