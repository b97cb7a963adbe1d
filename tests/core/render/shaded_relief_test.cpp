#include "strahler/render/shaded_relief.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace strahler::render {
namespace {

int brightness(Colour c) {
  return c[0] + c[1] + c[2];
}

TEST(HypsometricTint, SeaIsBlueAndDarkerWhenDeeper) {
  for (double h : {-0.5, -10.0, -60.0, -120.0, -3000.0}) {
    const Colour c = hypsometricTint(h);
    EXPECT_GT(c[2], c[0]) << h;
    EXPECT_GT(c[2], c[1]) << h;
  }
  EXPECT_EQ(hypsometricTint(-60.0), (Colour{50, 95, 155})); // half way to the deepest blue
  EXPECT_LT(brightness(hypsometricTint(-100.0)), brightness(hypsometricTint(-10.0)));
  EXPECT_EQ(hypsometricTint(-120.0), (Colour{30, 60, 120}));
  EXPECT_EQ(hypsometricTint(-5000.0), hypsometricTint(-120.0)); // deepest blue below 120 m
}

TEST(HypsometricTint, LowlandGreenThenBrownThenGreyThenWhite) {
  const Colour low = hypsometricTint(0.0), brown = hypsometricTint(800.0),
               grey = hypsometricTint(1400.0), high = hypsometricTint(2200.0);
  EXPECT_EQ(low, (Colour{92, 140, 78}));
  EXPECT_GT(low[1], low[0]); // green
  EXPECT_GT(low[1], low[2]);
  EXPECT_EQ(brown, (Colour{160, 122, 86}));
  EXPECT_GT(brown[0], brown[1]); // red over green over blue: brown
  EXPECT_GT(brown[1], brown[2]);
  EXPECT_EQ(grey, (Colour{140, 130, 124}));
  EXPECT_EQ(high, (Colour{240, 240, 240}));
  EXPECT_EQ(hypsometricTint(8000.0), high); // white above the last stop
  // Linear between stops: half way from 0 m to 150 m.
  EXPECT_EQ(hypsometricTint(75.0), (Colour{112, 153, 85}));
}

TEST(Hillshade, FlatGroundIsThreeQuartersAndTheSunnySlopeIsBrighter) {
  EXPECT_DOUBLE_EQ(hillshade(0.0, 0.0), 0.75);
  // The sun stands in the north-west: ground rising to the south-east faces it, ground
  // rising to the north-west faces away.
  const double facing = hillshade(0.2, -0.2), away = hillshade(-0.2, 0.2);
  EXPECT_GT(facing, 0.75);
  EXPECT_LT(away, 0.75);
  EXPECT_GT(hillshade(0.3, 0.0), hillshade(-0.3, 0.0)); // rising east faces the western sun
  EXPECT_GT(hillshade(0.0, -0.3), hillshade(0.0, 0.3)); // rising south faces the northern sun
  // Facing the sun square on (altitude 45°): the brightest, 0.75·√2.
  const double s = 0.5 / std::sqrt(2.0); // slope 1/2 before the 2× exaggeration
  EXPECT_NEAR(hillshade(s, -s), 0.75 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(hillshade(-5.0, 5.0), 0.0); // a steep slope in its own shadow: black, not negative
}

TEST(ReliefColour, ShadesLandAndLeavesWaterUnshaded) {
  EXPECT_EQ(reliefColour(-20.0, 0.1), hypsometricTint(-20.0));
  EXPECT_EQ(reliefColour(800.0, 0.5), (Colour{80, 61, 43}));
  EXPECT_EQ(reliefColour(2200.0, 1.2), (Colour{255, 255, 255})); // clamped
}

/// Heights of the plane h = a·x + b·y + c at bordered samples spaced `step` apart (y up).
std::vector<double> plane(int width, int height, double step, double a, double b, double c) {
  std::vector<double> h;
  for (int j = 0; j < height + 2; ++j)
    for (int i = 0; i < width + 2; ++i)
      h.push_back(a * i * step - b * j * step + c);
  return h;
}

TEST(ShadeRelief, APlaneIsOneColourShadedByItsSlope) {
  const int w = 5, h = 3;
  const std::vector<double> spacing(h + 2, 10.0);
  const image::RgbImage img = shadeRelief(plane(w, h, 10.0, 0.1, -0.05, 300.0), w, h, spacing);
  ASSERT_EQ(img.width, w);
  ASSERT_EQ(img.height, h);
  ASSERT_EQ(img.pixels.size(), static_cast<std::size_t>(w * h * 3));
  // The centre pixel (2, 1) is bordered sample (3, 2): 300 + 0.1·30 + 0.05·20 = 304 m.
  const Colour centre = reliefColour(304.0, hillshade(0.1, -0.05));
  const std::size_t i = (1 * w + 2) * 3;
  EXPECT_EQ((Colour{img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]}), centre);
}

TEST(ShadeRelief, ACutOutOfALargerRasterHasItsPixelsExactly) {
  // Rough terrain on a 12 × 9 raster; the 5 × 4 raster at pixel (4, 3) with its border cut
  // from the same heights (as a tile and its neighbours' edge pixels) gives the same pixels.
  const int W = 12, H = 9, w = 5, h = 4, x0 = 4, y0 = 3;
  std::vector<double> big;
  for (int j = 0; j < H + 2; ++j)
    for (int i = 0; i < W + 2; ++i)
      big.push_back(200.0 + 80.0 * std::sin(0.9 * i) * std::cos(1.3 * j) - 3.0 * i * j);
  std::vector<double> spacing(H + 2);
  for (int j = 0; j < H + 2; ++j)
    spacing[static_cast<std::size_t>(j)] = 30.0 + 0.5 * j; // varies by row, as in Web Mercator
  const image::RgbImage whole = shadeRelief(big, W, H, spacing);
  std::vector<double> cut;
  for (int j = y0; j < y0 + h + 2; ++j)
    for (int i = x0; i < x0 + w + 2; ++i)
      cut.push_back(big[static_cast<std::size_t>(j * (W + 2) + i)]);
  const std::vector<double> cutSpacing(spacing.begin() + y0, spacing.begin() + y0 + h + 2);
  const image::RgbImage part = shadeRelief(cut, w, h, cutSpacing);
  int shaded = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 3; ++k) {
        const std::uint8_t p = part.pixels[static_cast<std::size_t>((y * w + x) * 3 + k)];
        ASSERT_EQ(p, whole.pixels[static_cast<std::size_t>(((y + y0) * W + x + x0) * 3 + k)])
            << x << "," << y;
        shaded += p != hypsometricTint(cut[static_cast<std::size_t>((y + 1) * (w + 2) + x + 1)])[k];
      }
  EXPECT_GT(shaded, 0); // the terrain is not flat: the shade changed pixels
}

} // namespace
} // namespace strahler::render
