#include "drainage_test_support.h"

#include "strahler/quality/drainage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

namespace strahler::quality {
namespace {

using test::landRaster;

constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};

bool isLand(const HeightRaster& r, int x, int y) {
  return r.cellClass[test::at(r, x, y)] == std::uint8_t(CellClass::kLand);
}

bool inside(const HeightRaster& r, int x, int y) {
  return x >= 0 && y >= 0 && x < r.width && y < r.height;
}

/// True if land cell (x, y) is on the border or next to water.
bool touchesSink(const HeightRaster& r, int x, int y) {
  for (int k = 0; k < 8; ++k)
    if (!inside(r, x + kDx[k], y + kDy[k]) || !isLand(r, x + kDx[k], y + kDy[k]))
      return true;
  return false;
}

/// Spill elevations by plain relaxation, S = max(h, min over neighbours of S), until stable.
std::vector<double> bruteForceSpill(const HeightRaster& r) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> spill(r.heights.size(), kInf);
  for (bool changed = true; changed;) {
    changed = false;
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x) {
        if (!isLand(r, x, y))
          continue;
        const std::size_t c = test::at(r, x, y);
        double lowest = touchesSink(r, x, y) ? -kInf : kInf;
        for (int k = 0; k < 8; ++k)
          if (inside(r, x + kDx[k], y + kDy[k]) && isLand(r, x + kDx[k], y + kDy[k]))
            lowest = std::min(lowest, spill[test::at(r, x + kDx[k], y + kDy[k])]);
        const double s = std::max(double(r.heights[c]), lowest);
        changed = changed || s != spill[c];
        spill[c] = s;
      }
  }
  return spill;
}

/// Cells of depressions deeper than `tolerance`, found from brute-force spill levels; returns
/// their number through `pits`.
std::vector<bool> bruteForcePitCells(const HeightRaster& r, double tolerance, std::size_t& pits) {
  const std::vector<double> spill = bruteForceSpill(r);
  const auto flooded = [&](int x, int y) {
    return inside(r, x, y) && isLand(r, x, y) &&
           spill[test::at(r, x, y)] > double(r.heights[test::at(r, x, y)]);
  };
  std::vector<bool> seen(spill.size(), false), inPit(spill.size(), false);
  pits = 0;
  for (int y0 = 0; y0 < r.height; ++y0)
    for (int x0 = 0; x0 < r.width; ++x0) {
      if (!flooded(x0, y0) || seen[test::at(r, x0, y0)])
        continue;
      std::vector<std::pair<int, int>> component{{x0, y0}};
      seen[test::at(r, x0, y0)] = true;
      double lowest = r.heights[test::at(r, x0, y0)];
      for (std::size_t i = 0; i < component.size(); ++i) {
        const auto [x, y] = component[i];
        lowest = std::min(lowest, double(r.heights[test::at(r, x, y)]));
        for (int k = 0; k < 8; ++k)
          if (flooded(x + kDx[k], y + kDy[k]) && !seen[test::at(r, x + kDx[k], y + kDy[k])]) {
            seen[test::at(r, x + kDx[k], y + kDy[k])] = true;
            component.emplace_back(x + kDx[k], y + kDy[k]);
          }
      }
      if (spill[test::at(r, x0, y0)] - lowest > tolerance) {
        ++pits;
        for (const auto& [x, y] : component)
          inPit[test::at(r, x, y)] = true;
      }
    }
  return inPit;
}

/// With no filling (tolerance 0) and distinct heights there are no flats, so a cell drains iff
/// plain D8 steepest descent on the terrain reaches a cell touching a sink.
bool bruteForceDescentDrains(const HeightRaster& r, int x, int y) {
  while (!touchesSink(r, x, y)) {
    double steepest = 0.0;
    int next = -1;
    for (int k = 0; k < 8; ++k) {
      const double run = (kDx[k] != 0 && kDy[k] != 0) ? std::sqrt(2.0) : 1.0;
      const double slope =
          (double(r.heights[test::at(r, x + kDx[k], y + kDy[k])]) - r.heights[test::at(r, x, y)]) /
          run;
      if (slope < steepest) {
        steepest = slope;
        next = k;
      }
    }
    if (next < 0)
      return false; // a local minimum
    x += kDx[next];
    y += kDy[next];
  }
  return true;
}

/// 24 x 24 cells: distinct integer heights (a random permutation) on a westward staircase, with
/// a few lake cells.
HeightRaster randomRaster(unsigned seed) {
  constexpr int kSide = 24;
  std::mt19937 random(seed);
  std::vector<int> perm(kSide * kSide);
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), random);
  HeightRaster r = landRaster(kSide, kSide, 5.0, [&](int x, int y) {
    return double(perm[std::size_t(y * kSide + x)]) + double(kSide * kSide) * double(x / 4);
  });
  std::uniform_int_distribution<int> cell(0, kSide * kSide - 1);
  for (int i = 0; i < 12; ++i)
    r.cellClass[std::size_t(cell(random))] = std::uint8_t(CellClass::kLake);
  return r;
}

TEST(DrainageProperties, PitsMatchBruteForceSpillLevels) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const HeightRaster r = randomRaster(seed);
    for (double tolerance : {0.0, 50.0, 400.0}) {
      std::size_t expectedPits = 0;
      const std::vector<bool> inPit = bruteForcePitCells(r, tolerance, expectedPits);
      const DrainageMap map = mapDrainage(r, tolerance);
      EXPECT_EQ(map.report.pits, expectedPits) << "seed " << seed << " tolerance " << tolerance;
      for (std::size_t c = 0; c < inPit.size(); ++c) {
        if (inPit[c]) {
          EXPECT_EQ(map.cells[c], CellDrainage::kUndrained) << "seed " << seed << " cell " << c;
        }
      }
    }
  }
}

TEST(DrainageProperties, WithoutFillingDrainageIsPlainSteepestDescent) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const HeightRaster r = randomRaster(seed);
    const DrainageMap map = mapDrainage(r, 0.0);
    std::size_t draining = 0;
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x) {
        if (!isLand(r, x, y))
          continue;
        const bool drains = bruteForceDescentDrains(r, x, y);
        draining += drains ? 1 : 0;
        EXPECT_EQ(map.cells[test::at(r, x, y)] == CellDrainage::kDrains, drains)
            << "seed " << seed << " cell " << x << "," << y;
      }
    EXPECT_EQ(map.report.drainingCells, draining);
    EXPECT_GT(map.report.pits, 0u) << "the raster should be rough enough to have pits";
  }
}

/// A w x w cone (no water: it drains off the border) falling `slope` m per cell, with an
/// egg-crate ripple of `amplitude` m and a period of 2π·20 cells.
HeightRaster rippledCone(int w, double slope, double amplitude) {
  const double c = 0.5 * (w - 1);
  return landRaster(w, w, 10.0, [&](int x, int y) {
    const double r = std::hypot(x - c, y - c);
    return 1000.0 - slope * r + amplitude * std::sin(x / 20.0) * std::sin(y / 20.0);
  });
}

TEST(DrainageProperties, RipplesBelowHalfTheToleranceNeverMakePits) {
  // Moving away from the summit one cell at a time never climbs the cone, so a cell's spill
  // level is at most 2 × amplitude above it: every depression is shallower than 0.9 m.
  const DrainageReport report = checkDrainage(rippledCone(500, 0.05, 0.45), 1.0);
  EXPECT_EQ(report.pits, 0u);
  EXPECT_EQ(report.drainingCells, report.landCells);
}

TEST(DrainageProperties, StrongRipplesMakePits) {
  const DrainageReport report = checkDrainage(rippledCone(300, 0.05, 5.0), 1.0);
  EXPECT_GT(report.pits, 0u);
  EXPECT_LT(report.drainingFraction, 1.0);
  EXPECT_GT(report.largestUndrainedAreaKm2, 0.0);
}

TEST(DrainageProperties, FourMillionCells) {
  const HeightRaster raster = rippledCone(2000, 0.05, 0.45);
  const auto start = std::chrono::steady_clock::now();
  const DrainageReport report = checkDrainage(raster, 1.0);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  std::printf("checkDrainage on 2000 x 2000 cells: %.2f s\n", elapsed.count());
  RecordProperty("seconds", std::to_string(elapsed.count()));
  EXPECT_EQ(report.landCells, 4'000'000u);
  EXPECT_EQ(report.drainingCells, report.landCells);
}

} // namespace
} // namespace strahler::quality
