#include "drainage_test_support.h"

#include "strahler/quality/drainage.h"

#include <gtest/gtest.h>

#include <cmath>

namespace strahler::quality {
namespace {

using test::at;
using test::countLand;
using test::landRaster;
using test::setClass;

constexpr int kSize = 41;
constexpr int kCentre = 20;
constexpr double kCellSize = 10.0;
constexpr double kCellAreaKm2 = kCellSize * kCellSize * 1e-6;

double radius(int x, int y) {
  return std::hypot(double(x - kCentre), double(y - kCentre));
}

/// A cone 100 m high falling 0.2 m per cell, in a sea that starts 19 cells from the summit.
HeightRaster coneIsland() {
  HeightRaster raster = landRaster(kSize, kSize, kCellSize, [](int x, int y) {
    return radius(x, y) >= 19.0 ? 0.0 : 100.0 - 0.2 * radius(x, y);
  });
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (radius(x, y) >= 19.0)
        setClass(raster, x, y, CellClass::kSea);
  return raster;
}

/// Lowers cell (x, y) by `depth` metres.
void dig(HeightRaster& raster, int x, int y, float depth) {
  raster.heights[at(raster, x, y)] -= depth;
}

/// A ring ridge 100 m high at 10 cells from the centre, falling 5 m per cell on both sides.
HeightRaster crater() {
  HeightRaster raster = landRaster(kSize, kSize, kCellSize, [](int x, int y) {
    return 100.0 - 5.0 * std::abs(radius(x, y) - 10.0);
  });
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (radius(x, y) >= 19.0)
        setClass(raster, x, y, CellClass::kSea);
  return raster;
}

TEST(Drainage, ConeIslandDrainsEverywhere) {
  const HeightRaster raster = coneIsland();
  const DrainageReport report = checkDrainage(raster);
  EXPECT_EQ(report.landCells, countLand(raster));
  EXPECT_EQ(report.drainingCells, report.landCells);
  EXPECT_DOUBLE_EQ(report.drainingFraction, 1.0);
  EXPECT_EQ(report.pits, 0u);
  EXPECT_DOUBLE_EQ(report.largestUndrainedAreaKm2, 0.0);
  EXPECT_DOUBLE_EQ(report.fillTolerance, 1.0);
}

TEST(Drainage, PitShallowerThanToleranceIsFilled) {
  HeightRaster raster = coneIsland();
  dig(raster, 25, 20, 0.5f); // about 0.28 m below its lowest neighbour
  const DrainageReport report = checkDrainage(raster, 1.0);
  EXPECT_EQ(report.drainingCells, report.landCells);
  EXPECT_EQ(report.pits, 0u);
}

TEST(Drainage, SameShallowPitCountsWithASmallerTolerance) {
  HeightRaster raster = coneIsland();
  dig(raster, 25, 20, 0.5f);
  const DrainageMap map = mapDrainage(raster, 0.1);
  EXPECT_EQ(map.report.pits, 1u);
  EXPECT_EQ(map.cells[at(raster, 25, 20)], CellDrainage::kUndrained);
}

TEST(Drainage, DeepPitAndItsCatchmentDoNotDrain) {
  HeightRaster raster = coneIsland();
  dig(raster, 25, 20, 2.0f);
  const DrainageMap map = mapDrainage(raster, 1.0);
  EXPECT_EQ(map.report.pits, 1u);
  EXPECT_EQ(map.cells[at(raster, 25, 20)], CellDrainage::kUndrained);
  EXPECT_EQ(map.cells[at(raster, 24, 20)], CellDrainage::kUndrained) << "upslope, flows in";
  EXPECT_EQ(map.cells[at(raster, 26, 20)], CellDrainage::kUndrained) << "the pit is below it";
  EXPECT_EQ(map.cells[at(raster, 27, 20)], CellDrainage::kDrains) << "downslope of the pit";
  EXPECT_EQ(map.cells[at(raster, 15, 20)], CellDrainage::kDrains) << "other side of the summit";
  const std::size_t undrained = map.report.landCells - map.report.drainingCells;
  EXPECT_GE(undrained, 2u);
  EXPECT_LT(map.report.drainingFraction, 1.0);
  // The catchment is one connected patch, whose water ends in the pit.
  EXPECT_NEAR(map.report.largestUndrainedAreaKm2, double(undrained) * kCellAreaKm2, 1e-12);
  EXPECT_DOUBLE_EQ(map.report.largestUndrainedAt.x, raster.origin.x + 25 * raster.cellSize);
  EXPECT_DOUBLE_EQ(map.report.largestUndrainedAt.y, raster.origin.y + 20 * raster.cellSize);
}

TEST(Drainage, DeepPitDrainsWithALargerTolerance) {
  HeightRaster raster = coneIsland();
  dig(raster, 25, 20, 2.0f);
  const DrainageReport report = checkDrainage(raster, 3.0);
  EXPECT_EQ(report.drainingCells, report.landCells);
  EXPECT_EQ(report.pits, 0u);
}

TEST(Drainage, SeparatePitsAreCountedSeparately) {
  HeightRaster raster = coneIsland();
  dig(raster, 25, 20, 2.0f);
  dig(raster, 14, 20, 2.0f);
  const DrainageMap map = mapDrainage(raster, 1.0);
  EXPECT_EQ(map.report.pits, 2u);
  EXPECT_EQ(map.cells[at(raster, 14, 20)], CellDrainage::kUndrained);
  const std::size_t undrained = map.report.landCells - map.report.drainingCells;
  EXPECT_LT(map.report.largestUndrainedAreaKm2, double(undrained) * kCellAreaKm2 - 1e-12);
}

TEST(Drainage, ClosedCraterIsAPit) {
  const HeightRaster raster = crater();
  const DrainageMap map = mapDrainage(raster);
  EXPECT_EQ(map.report.pits, 1u);
  EXPECT_EQ(map.cells[at(raster, kCentre, kCentre)], CellDrainage::kUndrained);
  EXPECT_EQ(map.cells[at(raster, kCentre + 5, kCentre)], CellDrainage::kUndrained);
  EXPECT_EQ(map.cells[at(raster, kCentre + 15, kCentre)], CellDrainage::kDrains);
}

TEST(Drainage, CraterWithALakeInsideDrains) {
  HeightRaster raster = crater();
  setClass(raster, kCentre, kCentre, CellClass::kLake);
  const DrainageMap map = mapDrainage(raster);
  EXPECT_EQ(map.report.landCells, countLand(raster));
  EXPECT_EQ(map.report.drainingCells, map.report.landCells);
  EXPECT_EQ(map.report.pits, 0u);
  EXPECT_EQ(map.cells[at(raster, kCentre, kCentre)], CellDrainage::kWater);
}

/// A 30 x 20 plateau at 10 m, walled at 20 m on the north, south and east borders, with the
/// sea in column 0 when `open`, a wall there too otherwise.
HeightRaster walledPlateau(bool open) {
  constexpr int w = 30, h = 20;
  HeightRaster raster = landRaster(w, h, kCellSize, [&](int x, int y) {
    const bool wall = y == 0 || y == h - 1 || x == w - 1 || (x == 0 && !open);
    return wall ? 20.0 : 10.0;
  });
  if (open)
    for (int y = 1; y < h - 1; ++y)
      setClass(raster, 0, y, CellClass::kSea);
  return raster;
}

TEST(Drainage, FlatPlateauNextToTheSeaDrains) {
  const DrainageReport report = checkDrainage(walledPlateau(true));
  EXPECT_EQ(report.drainingCells, report.landCells);
  EXPECT_EQ(report.pits, 0u);
}

TEST(Drainage, WalledFlatWithoutOutletIsAPit) {
  const HeightRaster raster = walledPlateau(false);
  const DrainageMap map = mapDrainage(raster);
  EXPECT_EQ(map.report.pits, 1u);
  const std::size_t walls = 2 * 30 + 2 * 18;
  EXPECT_EQ(map.report.drainingCells, walls);
  EXPECT_NEAR(map.report.largestUndrainedAreaKm2, 28.0 * 18.0 * kCellAreaKm2, 1e-12);
}

TEST(Drainage, ShoreCellIsAnOutletOfAWalledBasin) {
  // The shoreline of a lake (or fjord) narrower than a cell crosses one cell of the walled
  // plateau: that cell lets the plateau's water out.
  HeightRaster raster = walledPlateau(false);
  setClass(raster, 15, 10, CellClass::kShore);
  const DrainageMap map = mapDrainage(raster);
  EXPECT_EQ(map.report.landCells, 30u * 20u) << "a shore cell is land";
  EXPECT_EQ(map.report.drainingCells, map.report.landCells);
  EXPECT_EQ(map.report.pits, 0u);
}

TEST(Drainage, FlatDrainsTowardItsOutletNotIntoANeighbouringPit) {
  // A pit dug in the open plateau catches its rim. Elsewhere the flat moves one column toward
  // the sea per step (breadth-first from the coast) and at most one row sideways, so cells west
  // of the pit, or too far south to reach its rim, still get to the sea.
  HeightRaster raster = walledPlateau(true);
  dig(raster, 20, 10, 5.0f);
  const DrainageMap map = mapDrainage(raster);
  EXPECT_EQ(map.report.pits, 1u);
  EXPECT_EQ(map.cells[at(raster, 20, 10)], CellDrainage::kUndrained);
  EXPECT_EQ(map.cells[at(raster, 21, 10)], CellDrainage::kUndrained) << "steep way into the pit";
  EXPECT_EQ(map.cells[at(raster, 5, 10)], CellDrainage::kDrains);
  EXPECT_EQ(map.cells[at(raster, 25, 2)], CellDrainage::kDrains);
}

TEST(Drainage, CellsOutsideTheRasterActAsSea) {
  // No water at all: a plane tilted toward the west border drains off the map.
  const HeightRaster plane = landRaster(25, 15, kCellSize, [](int x, int) { return 0.5 * x; });
  const DrainageReport report = checkDrainage(plane);
  EXPECT_EQ(report.landCells, 25u * 15u);
  EXPECT_EQ(report.drainingCells, report.landCells);
}

TEST(Drainage, OnlyTheBorderOfABowlDrains) {
  const HeightRaster bowl = landRaster(
      kSize, kSize, kCellSize, [](int x, int y) { return 0.1 * radius(x, y) * radius(x, y); });
  const DrainageMap map = mapDrainage(bowl);
  EXPECT_EQ(map.report.drainingCells, std::size_t(4 * kSize - 4));
  EXPECT_EQ(map.report.pits, 1u);
  EXPECT_EQ(map.cells[at(bowl, 0, 0)], CellDrainage::kDrains);
  EXPECT_EQ(map.cells[at(bowl, 1, 1)], CellDrainage::kUndrained);
}

TEST(Drainage, RasterWithoutLandDrainsTrivially) {
  HeightRaster sea = landRaster(4, 3, kCellSize, [](int, int) { return 0.0; });
  sea.cellClass.assign(sea.cellClass.size(), std::uint8_t(CellClass::kSea));
  const DrainageReport report = checkDrainage(sea);
  EXPECT_EQ(report.landCells, 0u);
  EXPECT_DOUBLE_EQ(report.drainingFraction, 1.0);
  const DrainageReport empty = checkDrainage(HeightRaster{});
  EXPECT_EQ(empty.landCells, 0u);
}

TEST(Drainage, MapAndReportAgree) {
  HeightRaster raster = coneIsland();
  dig(raster, 25, 20, 2.0f);
  const DrainageMap map = mapDrainage(raster);
  std::size_t draining = 0;
  for (CellDrainage c : map.cells)
    draining += c == CellDrainage::kDrains ? 1 : 0;
  EXPECT_EQ(draining, map.report.drainingCells);
  EXPECT_EQ(checkDrainage(raster).drainingCells, map.report.drainingCells);
}

} // namespace
} // namespace strahler::quality
