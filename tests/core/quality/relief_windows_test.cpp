#include "strahler/quality/dem_file.h"
#include "strahler/quality/relief_windows.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace strahler::quality {
namespace {

/// A reference DEM of ../shared/reference, or "" when it is absent outside CI (in CI, with
/// CI=true, an absent file fails the test instead).
std::string referenceDem(const std::string& name) {
  const std::string path = std::string(STRAHLER_REFERENCE_DIR) + "/" + name;
  if (std::filesystem::exists(path))
    return path;
  const char* ci = std::getenv("CI");
  if (ci != nullptr && std::string(ci) == "true")
    ADD_FAILURE() << path << " is absent (CI must have ../shared/reference)";
  return "";
}

/// An all-land raster of 120 × 100 cells of 30 m, flat at 10 m.
HeightRaster flatLand() {
  HeightRaster r;
  r.width = 120;
  r.height = 100;
  r.cellSize = 30.0;
  r.heights.assign(std::size_t(r.width * r.height), 10.0f);
  r.cellClass.assign(r.heights.size(), std::uint8_t(CellClass::kLand));
  return r;
}

float& heightAt(HeightRaster& r, int x, int y) {
  return r.heights[std::size_t(y * r.width + x)];
}

TEST(ReliefWindows, TheHighestReliefWindowsOnLandWithoutOverlap) {
  HeightRaster r = flatLand();
  heightAt(r, 100, 90) = 500.0f; // north-east: relief 490
  heightAt(r, 10, 5) = 300.0f;   // south-west: relief 290
  heightAt(r, 12, 6) = 900.0f;   // ... but a sea cell beside it rules those windows out
  for (int y = 0; y < 12; ++y)
    r.cellClass[std::size_t(y * r.width + 20)] = std::uint8_t(CellClass::kSea);
  const std::vector<WindowPlacement> windows = selectReliefWindows(r, 40, 3);
  ASSERT_GE(windows.size(), 2u);
  // Rows from the north edge: raster row 90 is row 9 from the north.
  EXPECT_DOUBLE_EQ(windows[0].reliefM, 490.0);
  EXPECT_LE(windows[0].row, 9);
  EXPECT_GT(windows[0].row + 40, 9);
  EXPECT_LE(windows[0].col, 100);
  EXPECT_GT(windows[0].col + 40, 100);
  for (const WindowPlacement& w : windows) {
    EXPECT_EQ(w.row % 5, 0) << "candidates every max(4, 40 / 8) = 5 cells";
    EXPECT_EQ(w.col % 5, 0);
  }
  for (std::size_t i = 0; i < windows.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_TRUE(std::abs(windows[i].row - windows[j].row) >= 40 ||
                  std::abs(windows[i].col - windows[j].col) >= 40);
  // The heights come north row first.
  const std::vector<double> z = windowHeights(r, windows[0], 40);
  const int rowInWindow = 9 - windows[0].row, colInWindow = 100 - windows[0].col;
  EXPECT_EQ(z[std::size_t(rowInWindow * 40 + colInWindow)], 500.0);
  EXPECT_TRUE(selectReliefWindows(r, 200, 3).empty()) << "larger than the raster";
}

TEST(ReliefWindows, MeasuresEachWindowAndSummarises) {
  HeightRaster r = flatLand();
  r.width = 200;
  r.heights.resize(std::size_t(r.width * r.height));
  r.cellClass.assign(r.heights.size(), std::uint8_t(CellClass::kLand));
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x)
      heightAt(r, x, y) = float(100.0 * std::sin(x * 0.21) * std::cos(y * 0.17) + 0.5 * x);
  const ReliefWindows w = measureReliefWindows(r, 1.5, 2);
  EXPECT_EQ(w.cells, 50);
  ASSERT_EQ(w.list.size(), 2u);
  for (std::size_t c = 0; c < kGeomorphonCount; ++c)
    EXPECT_NEAR(w.meanGeomorphons[c], (w.list[0].geomorphons[c] + w.list[1].geomorphons[c]) / 2.0,
                1e-12);
  EXPECT_NEAR(w.medianSpectralSlope, (w.list[0].spectralSlope + w.list[1].spectralSlope) / 2.0,
              1e-12);
}

TEST(ReliefWindows, ResamplingAsScipyZoom) {
  // 120 x 100 cells of 30 m to 90 m: 40 x 33 cells (100 / 3 = 33.3); output column j samples
  // input column j · 119 / 39, so a plane stays the same plane.
  HeightRaster r = flatLand();
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x)
      heightAt(r, x, y) = float(2.0 * x + 0.5 * y);
  r.cellClass[std::size_t(50 * r.width + 61)] = std::uint8_t(CellClass::kSea);
  const HeightRaster coarse = resampleRaster(r, 90.0);
  EXPECT_EQ(coarse.width, 40);
  EXPECT_EQ(coarse.height, 33);
  EXPECT_EQ(coarse.cellSize, 90.0);
  const double sx = 119.0 / 39.0, sy = 99.0 / 32.0;
  for (int y = 0; y < coarse.height; ++y)
    for (int x = 0; x < coarse.width; ++x)
      EXPECT_NEAR(coarse.heights[std::size_t(y * coarse.width + x)], 2.0 * x * sx + 0.5 * y * sy,
                  1e-3)
          << x << " " << y;
  // Input (61, 50) is mixed into output column 20 (at 61.03) of row 16 (at 49.5): outside.
  std::size_t outside = 0;
  for (std::uint8_t c : coarse.cellClass)
    outside += c != std::uint8_t(CellClass::kLand) ? 1 : 0;
  EXPECT_EQ(coarse.cellClass[std::size_t(16 * coarse.width + 20)], std::uint8_t(CellClass::kSea));
  EXPECT_GE(outside, 1u);
  EXPECT_LE(outside, 4u);
}

/// The 5 km windows of Big Tujunga west at 30 m: blind_set.py's own figures (numpy), computed
/// by importing its windows(), spectral_slope() and geomorphons() on the same file:
///   h, cell, valid = read_dem(path); for y, x in windows(h, valid, 167, 3): ...
struct PythonWindow {
  int row, col;
  double relief, spectral;
  std::array<double, kGeomorphonCount> shares;
};
constexpr PythonWindow kBigTujunga5Km[] = {
    {300,
     220,
     1159.0,
     4.552513,
     {0.0, 0.006504, 0.084503, 4.9e-05, 0.214094, 0.37596, 0.179226, 4.9e-05, 0.125581, 0.014035}},
    {440,
     420,
     1116.0,
     4.647714,
     {0.0, 0.011052, 0.086166, 9.8e-05, 0.194728, 0.393907, 0.17727, 9.8e-05, 0.128417, 0.008264}},
    {0,
     360,
     1100.0,
     4.802850,
     {0.0, 0.009438, 0.092132, 0.000147, 0.202846, 0.417184, 0.199765, 9.8e-05, 0.078097,
      0.000293}},
};

TEST(ReliefWindows, BigTujungaGivesBlindSetsFigures) {
  const std::string path = referenceDem("bigtujunga-west-30m.asc");
  if (path.empty())
    GTEST_SKIP() << "../shared/reference/bigtujunga-west-30m.asc is absent";
  const auto raster = readDemFile(path, std::nullopt);
  ASSERT_TRUE(raster.ok()) << raster.error().message;
  const ReliefWindows five = measureReliefWindows(raster.value(), 5.0, 3);
  EXPECT_EQ(five.cells, 167);
  ASSERT_EQ(five.list.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const PythonWindow& want = kBigTujunga5Km[i];
    const ReliefWindow& got = five.list[i];
    EXPECT_EQ(got.placement.row, want.row) << i;
    EXPECT_EQ(got.placement.col, want.col) << i;
    EXPECT_NEAR(got.placement.reliefM, want.relief, 0.01) << i;
    EXPECT_NEAR(got.spectralSlope, want.spectral, 0.02) << i;
    for (std::size_t c = 0; c < kGeomorphonCount; ++c)
      EXPECT_NEAR(got.geomorphons[c], want.shares[c], 0.002) << i << " " << kGeomorphonNames[c];
  }
  EXPECT_NEAR(five.medianSpectralSlope, 4.647714, 0.02);
  // The default 7.5 km: one window wholly inside the catchment, (155, 248) in blind_set.py.
  const ReliefWindows wide = measureReliefWindows(raster.value());
  ASSERT_EQ(wide.list.size(), 1u);
  EXPECT_EQ(wide.list[0].placement.row, 155);
  EXPECT_EQ(wide.list[0].placement.col, 248);
  EXPECT_NEAR(wide.list[0].spectralSlope, 4.599328, 0.02);
  EXPECT_NEAR(wide.meanGeomorphons[std::size_t(Geomorphon::kHollow)], 0.190814, 0.002);
  EXPECT_NEAR(wide.meanGeomorphons[std::size_t(Geomorphon::kSlope)], 0.391554, 0.002);
  EXPECT_NEAR(wide.meanGeomorphons[std::size_t(Geomorphon::kValley)], 0.106332, 0.002);
  EXPECT_NEAR(wide.meanGeomorphons[std::size_t(Geomorphon::kRidge)], 0.095681, 0.002);
  // Resampled to 90 m as the script's --cell 90 does (scipy.ndimage.zoom): 214 x 200 cells,
  // windows of 83 cells.
  const HeightRaster coarse = resampleRaster(raster.value(), 90.0);
  EXPECT_EQ(coarse.width, 200);
  EXPECT_EQ(coarse.height, 214);
  const ReliefWindows at90 = measureReliefWindows(coarse);
  ASSERT_EQ(at90.list.size(), 3u);
  constexpr PythonWindow kAt90[] = {
      {40,
       90,
       1393.095,
       3.871606,
       {0.0, 0.015467, 0.150933, 0.0, 0.187733, 0.300978, 0.174933, 0.0, 0.162844, 0.007111}},
      {70,
       0,
       1148.54,
       4.005216,
       {0.0, 0.009778, 0.127289, 0.000356, 0.2016, 0.3296, 0.1712, 0.000178, 0.154311, 0.005689}},
      {130,
       110,
       1122.16,
       3.785791,
       {0.0, 0.013333, 0.128178, 0.0, 0.205511, 0.315556, 0.170844, 0.0, 0.153244, 0.013333}},
  };
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(at90.list[i].placement.row, kAt90[i].row) << i;
    EXPECT_EQ(at90.list[i].placement.col, kAt90[i].col) << i;
    EXPECT_NEAR(at90.list[i].placement.reliefM, kAt90[i].relief, 0.01) << i;
    EXPECT_NEAR(at90.list[i].spectralSlope, kAt90[i].spectral, 0.02) << i;
    for (std::size_t c = 0; c < kGeomorphonCount; ++c)
      EXPECT_NEAR(at90.list[i].geomorphons[c], kAt90[i].shares[c], 0.002) << i;
  }
}

/// The same on the 3 arc-second White Mountains grid (degrees: its columns are resampled to
/// square cells of 92.77 m, as blind_set.py's read_asc does) and the Orkhon valley (91.67 m).
TEST(ReliefWindows, TheNinetyMetreReferencesGiveBlindSetsFigures) {
  const std::string white = referenceDem("white-mountains-west-3arcsec.asc");
  const std::string orkhon = referenceDem("orkhon-valley-92m.asc");
  if (white.empty() || orkhon.empty())
    GTEST_SKIP() << "../shared/reference is absent";
  constexpr PythonWindow kWhite[] = {
      {930,
       230,
       1290.084,
       4.428229,
       {0.0, 0.005067, 0.059111, 0.000375, 0.19666, 0.530869, 0.127979, 0.002815, 0.076187,
        0.000938}},
      {1020,
       270,
       1221.143,
       5.318650,
       {0.0, 0.00638, 0.091574, 0.0, 0.196472, 0.449615, 0.16307, 0.0, 0.092513, 0.000375}},
      {1120,
       70,
       1193.625,
       4.808615,
       {0.001501, 0.00638, 0.079189, 0.000563, 0.188403, 0.523926, 0.108088, 0.007318, 0.083505,
        0.001126}},
  };
  const auto grid = readDemFile(white, std::nullopt);
  ASSERT_TRUE(grid.ok()) << grid.error().message;
  EXPECT_EQ(grid.value().width, 428);
  EXPECT_EQ(grid.value().height, 1201);
  EXPECT_NEAR(grid.value().cellSize, 92.766, 0.001);
  const ReliefWindows w = measureReliefWindows(grid.value());
  ASSERT_EQ(w.list.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(w.list[i].placement.row, kWhite[i].row) << i;
    EXPECT_EQ(w.list[i].placement.col, kWhite[i].col) << i;
    EXPECT_NEAR(w.list[i].placement.reliefM, kWhite[i].relief, 0.01) << i;
    EXPECT_NEAR(w.list[i].spectralSlope, kWhite[i].spectral, 0.02) << i;
    for (std::size_t c = 0; c < kGeomorphonCount; ++c)
      EXPECT_NEAR(w.list[i].geomorphons[c], kWhite[i].shares[c], 0.002) << i;
  }
  const auto valley = readDemFile(orkhon, std::nullopt);
  ASSERT_TRUE(valley.ok()) << valley.error().message;
  const ReliefWindows o = measureReliefWindows(valley.value());
  ASSERT_EQ(o.list.size(), 1u);
  EXPECT_EQ(o.list[0].placement.row, 30);
  EXPECT_EQ(o.list[0].placement.col, 10);
  EXPECT_NEAR(o.list[0].spectralSlope, 4.797909, 0.02);
  EXPECT_NEAR(o.list[0].geomorphons[std::size_t(Geomorphon::kHollow)], 0.145727, 0.002);
  EXPECT_NEAR(o.list[0].geomorphons[std::size_t(Geomorphon::kValley)], 0.143901, 0.002);
}

} // namespace
} // namespace strahler::quality
