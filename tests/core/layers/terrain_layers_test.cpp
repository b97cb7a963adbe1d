// The layer maths on synthetic height grids: known slopes and aspects, the sky view of open and
// enclosed ground, the sediment and humidity rules, and that a raster cut out of a larger one
// (a tile with its neighbours' samples as border) gives the larger one's values exactly.
#include "strahler/layers/humidity.h"
#include "strahler/layers/sediment.h"
#include "strahler/layers/sky_view.h"
#include "strahler/layers/slope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace strahler::layers {
namespace {

/// A bordered raster of heights f(global x, global y), pixel (0, 0) at global (x0, y0).
struct Raster {
  std::vector<double> heights, spacing;
  BorderedHeights grid;

  Raster(int width, int height, int border, double step, int x0, int y0,
         const std::function<double(int, int)>& f) {
    for (int y = -border; y < height + border; ++y)
      for (int x = -border; x < width + border; ++x)
        heights.push_back(f(x0 + x, y0 + y));
    spacing.assign(static_cast<std::size_t>(height + 2 * border), step);
    grid = {heights, width, height, border, spacing};
  }
};

/// Rolling hills, in m, over global pixel indices at 10 m spacing.
double hills(int x, int y) {
  return 80.0 * std::sin(x * 0.11) * std::cos(y * 0.07) + 30.0 * std::sin((x + 2 * y) * 0.23);
}

TEST(Slope, APlaneHasItsSlopeAndFacesDownhill) {
  // Rising 1 m per 10 m pixel eastward: 5.71°, facing west (270°).
  const Raster east(8, 8, 1, 10.0, 0, 0, [](int x, int) { return 1.0 * x; });
  for (double s : slopeDegrees(east.grid))
    EXPECT_NEAR(s, std::atan(0.1) * 180.0 / M_PI, 1e-9);
  for (double a : aspectDegrees(east.grid))
    EXPECT_NEAR(a, 270.0, 1e-9);
  // Rising to the north (rows run south, so heights fall with y): facing south (180°).
  const Raster north(8, 8, 1, 10.0, 0, 0, [](int, int y) { return -2.0 * y; });
  for (double a : aspectDegrees(north.grid))
    EXPECT_NEAR(a, 180.0, 1e-9);
  const Raster flat(4, 4, 1, 10.0, 0, 0, [](int, int) { return 5.0; });
  for (double a : aspectDegrees(flat.grid))
    EXPECT_EQ(a, kFlatAspect);
  for (double s : slopeDegrees(flat.grid))
    EXPECT_EQ(s, 0.0);
}

TEST(SkyView, OpenGroundSeesTheWholeSkyAndAPitLess) {
  const int border = SkyView::kReach + 1;
  const Raster flat(16, 16, border, 10.0, 0, 0, [](int, int) { return 3.0; });
  for (double v : skyView(flat.grid))
    EXPECT_DOUBLE_EQ(v, 1.0);
  // A bowl: the centre sees less sky than its rim, and every value is in [0, 1].
  const Raster bowl(16, 16, border, 10.0, 0, 0,
                    [](int x, int y) { return 0.5 * ((x - 8) * (x - 8) + (y - 8) * (y - 8)); });
  const std::vector<double> v = skyView(bowl.grid);
  for (double s : v) {
    EXPECT_GE(s, 0.0);
    EXPECT_LE(s, 1.0);
  }
  EXPECT_LT(v[8 * 16 + 8], 0.8);
  // A peak sees all of it.
  const Raster peak(16, 16, border, 10.0, 0, 0,
                    [](int x, int y) { return -0.5 * ((x - 8) * (x - 8) + (y - 8) * (y - 8)); });
  EXPECT_DOUBLE_EQ(skyView(peak.grid)[8 * 16 + 8], 1.0);
}

TEST(SkyView, TheCoarseStepComputesEveryOtherPixelAndInterpolatesTheRest) {
  const int border = SkyView::kReach + 1;
  const Raster r(32, 32, border, 10.0, 64, 32, hills);
  const std::vector<double> fine = skyView(r.grid, 1), coarse = skyView(r.grid, 2);
  for (int y = 0; y < 32; y += 2)
    for (int x = 0; x < 32; x += 2)
      EXPECT_EQ(coarse[static_cast<std::size_t>(y * 32 + x)],
                fine[static_cast<std::size_t>(y * 32 + x)]);
  EXPECT_DOUBLE_EQ(coarse[1 * 32 + 1], 0.25 * (fine[0] + fine[2] + fine[64] + fine[66]));
}

/// `layer` of two side-by-side tiles and of one raster holding both agree pixel for pixel.
void expectSeamless(int border,
                    const std::function<std::vector<double>(const BorderedHeights&)>& layer) {
  const int n = 32;
  const Raster whole(2 * n, n, border, 10.0, 0, 0, hills);
  const Raster west(n, n, border, 10.0, 0, 0, hills), east(n, n, border, 10.0, n, 0, hills);
  const std::vector<double> all = layer(whole.grid), a = layer(west.grid), b = layer(east.grid);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      ASSERT_EQ(a[static_cast<std::size_t>(y * n + x)],
                all[static_cast<std::size_t>(y * 2 * n + x)])
          << x << "," << y;
      ASSERT_EQ(b[static_cast<std::size_t>(y * n + x)],
                all[static_cast<std::size_t>(y * 2 * n + n + x)])
          << x << "," << y;
    }
}

TEST(Layers, TilesCutFromOneRasterGiveItsValuesExactly) {
  expectSeamless(1, slopeDegrees);
  expectSeamless(1, aspectDegrees);
  expectSeamless(1, sedimentThickness);
  expectSeamless(SkyView::kReach + 1, [](const BorderedHeights& g) { return skyView(g, 2); });
  expectSeamless(SkyView::kReach, [](const BorderedHeights& g) { return skyView(g, 1); });
}

TEST(Sediment, NoneAtTheAngleOfReposeHalfOnAPlaneMoreInAHollow) {
  const Raster steep(4, 4, 1, 10.0, 0, 0, [](int x, int) { return 10.0 * x; }); // 45°
  for (double s : sedimentThickness(steep.grid))
    EXPECT_NEAR(s, 0.0, 1e-12);
  const Raster flat(4, 4, 1, 10.0, 0, 0, [](int, int) { return 1.0; });
  for (double s : sedimentThickness(flat.grid))
    EXPECT_DOUBLE_EQ(s, 0.5 * Sediment::kMaxM);
  const Raster hollow(5, 5, 1, 10.0, 0, 0,
                      [](int x, int y) { return 0.2 * ((x - 2) * (x - 2) + (y - 2) * (y - 2)); });
  const Raster crest(5, 5, 1, 10.0, 0, 0,
                     [](int x, int y) { return -0.2 * ((x - 2) * (x - 2) + (y - 2) * (y - 2)); });
  EXPECT_GT(sedimentThickness(hollow.grid)[12], 0.5 * Sediment::kMaxM);
  EXPECT_LT(sedimentThickness(crest.grid)[12], 0.5 * Sediment::kMaxM);
}

TEST(Humidity, WaterIsWetRiversWetTheirBanksFlatGroundKeepsSome) {
  const Raster r(4, 1, 1, 10.0, 0, 0, [](int x, int) { return x == 0 ? -1.0 : 5.0; });
  std::vector<double> wetness(4, 0.0);
  wetness[2] = 0.9; // pixel (2, 0): by a river
  const std::vector<double> h = humidity(r.grid, wetness);
  EXPECT_EQ(h[0], 1.0); // below sea level
  EXPECT_DOUBLE_EQ(h[2], 0.9);
  // Pixel 1 is flat but for its western neighbour's drop (a hollow's opposite): the local index.
  EXPECT_GT(h[3], 0.0);
  EXPECT_LE(h[3], Humidity::kLocalWeight);
}

} // namespace
} // namespace strahler::layers
