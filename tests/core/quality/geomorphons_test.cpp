#include "strahler/quality/geomorphons.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace strahler::quality {
namespace {

constexpr double kCell = 30.0; // with the default 360 m lookup: L = 12 cells
constexpr int kSize = 41;      // 41 x 41 cells, the centre at (20, 20)

/// An all-land raster of kSize² cells with heights z(x, y) in metres (x, y in cells from the
/// centre).
HeightRaster surface(const std::function<double(double, double)>& z) {
  HeightRaster r;
  r.width = r.height = kSize;
  r.cellSize = kCell;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      r.heights.push_back(float(z(x - kSize / 2, y - kSize / 2)));
  r.cellClass.assign(r.heights.size(), std::uint8_t(CellClass::kLand));
  return r;
}

Geomorphon at(const std::vector<Geomorphon>& classes, int x, int y) {
  return classes[std::size_t(y * kSize + x)];
}

TEST(Geomorphons, ThePublishedTableCornersAndLookup) {
  EXPECT_EQ(geomorphonLookupCells({}, 30.0), 12);
  EXPECT_EQ(geomorphonLookupCells({}, 90.0), 4);
  EXPECT_EQ(geomorphonLookupCells({}, 500.0), 2) << "at least 2 cells";
  EXPECT_STREQ(kGeomorphonNames[std::size_t(Geomorphon::kHollow)], "hollow");
}

TEST(Geomorphons, APlaneIsAllSlope) {
  // East, north-east and south-east look up (5.7° and 4.0°), their opposites down, north and
  // south are level: 3 up, 3 down is "slope".
  const HeightRaster plane = surface([](double x, double y) { return 500 + 3.0 * x + 0 * y; });
  const std::vector<Geomorphon> classes = classifyGeomorphons(plane);
  for (int y = 12; y < kSize - 12; ++y)
    for (int x = 12; x < kSize - 12; ++x)
      EXPECT_EQ(at(classes, x, y), Geomorphon::kSlope) << x << " " << y;
  // Nearer the edge than L, the padding (the edge height repeated) looks level: on the west
  // edge nothing looks down (3 up: footslope), on the east edge nothing up (3 down: shoulder).
  EXPECT_EQ(at(classes, 0, 20), Geomorphon::kFootslope);
  EXPECT_EQ(at(classes, kSize - 1, 20), Geomorphon::kShoulder);
  std::vector<double> z(plane.heights.begin(), plane.heights.end());
  const GeomorphonShares shares = windowGeomorphonShares(z, kSize, kSize, kCell);
  EXPECT_DOUBLE_EQ(shares[std::size_t(Geomorphon::kSlope)], 1.0);
}

TEST(Geomorphons, LevelGroundIsFlat) {
  const HeightRaster level = surface([](double x, double y) { return 100 + 0.001 * (x + y); });
  const GeomorphonShares shares = geomorphonShares(level);
  EXPECT_DOUBLE_EQ(shares[std::size_t(Geomorphon::kFlat)], 1.0);
}

TEST(Geomorphons, AConeHasItsPeakAtTheCentreAndAPitWhenInverted) {
  const auto cone = [](double x, double y) { return 1000 - 10.0 * std::hypot(x, y); };
  const std::vector<Geomorphon> peak = classifyGeomorphons(surface(cone));
  EXPECT_EQ(at(peak, 20, 20), Geomorphon::kPeak);
  // On the flank every direction but the one up the cone and its neighbours looks down.
  EXPECT_NE(at(peak, 30, 20), Geomorphon::kPeak);
  const std::vector<Geomorphon> pit =
      classifyGeomorphons(surface([&](double x, double y) { return 2000 - cone(x, y); }));
  EXPECT_EQ(at(pit, 20, 20), Geomorphon::kPit);
}

TEST(Geomorphons, AVValleyHasValleyCellsOnItsAxisAndARidgeWhenInverted) {
  // Sides of 20 % across x; a floor falling 0.3 % along y (level to the 1° threshold).
  const auto valley = [](double x, double y) { return 200 + 6.0 * std::abs(x) + 0.1 * y; };
  const std::vector<Geomorphon> v = classifyGeomorphons(surface(valley));
  const std::vector<Geomorphon> r =
      classifyGeomorphons(surface([&](double x, double y) { return 1000 - valley(x, y); }));
  for (int y = 12; y <= 28; ++y) {
    EXPECT_EQ(at(v, 20, y), Geomorphon::kValley) << y;
    EXPECT_EQ(at(r, 20, y), Geomorphon::kRidge) << y;
    // Farther from the axis than the lookup, the side is a plain slope.
    EXPECT_EQ(at(v, 20 + 13, y), Geomorphon::kSlope) << y;
    EXPECT_EQ(at(v, 20 - 13, y), Geomorphon::kSlope) << y;
  }
}

TEST(Geomorphons, WindowSharesCountOnlyCellsALookupFromTheEdge) {
  // A valley only in the outer band: the interior (cells 12..28) is a plain, all slope.
  std::vector<double> z(std::size_t(kSize * kSize));
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      z[std::size_t(y * kSize + x)] = 3.0 * x + (x < 3 ? 500.0 : 0.0);
  GeomorphonShares shares = windowGeomorphonShares(z, kSize, kSize, kCell);
  EXPECT_GT(shares[std::size_t(Geomorphon::kSlope)], 0.0);
  double total = 0.0;
  for (double s : shares)
    total += s;
  EXPECT_NEAR(total, 1.0, 1e-12);
  // Fewer than 2·L + 1 cells across: no interior.
  shares = windowGeomorphonShares(std::vector<double>(24 * 24, 1.0), 24, 24, kCell);
  EXPECT_TRUE(std::isnan(shares[0]));
}

TEST(Geomorphons, LookupsStopAtWater) {
  // A plane whose west half is sea: the land cells next to it see only the east, north and
  // south, so they are not classified as on an unbroken slope.
  HeightRaster plane = surface([](double x, double y) { return 500 + 3.0 * x + 0 * y; });
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < 20; ++x)
      plane.cellClass[std::size_t(y * kSize + x)] = std::uint8_t(CellClass::kSea);
  const std::vector<Geomorphon> classes = classifyGeomorphons(plane);
  // East, north-east and south-east look up, north and south are level, the west is sea:
  // 3 up and none down is a footslope.
  EXPECT_EQ(at(classes, 20, 20), Geomorphon::kFootslope);
  EXPECT_EQ(at(classes, 35, 20), Geomorphon::kSlope);
}

TEST(Geomorphons, DistanceIsHalfTheL1Difference) {
  GeomorphonShares a{}, b{};
  a[std::size_t(Geomorphon::kSlope)] = 1.0;
  b[std::size_t(Geomorphon::kSlope)] = 0.6;
  b[std::size_t(Geomorphon::kHollow)] = 0.4;
  EXPECT_NEAR(geomorphonDistance(a, b), 0.4, 1e-12);
  EXPECT_DOUBLE_EQ(geomorphonDistance(a, a), 0.0);
}

} // namespace
} // namespace strahler::quality
