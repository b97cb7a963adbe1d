// Bins (core/tiling/src/bins.h, private to the tiling module): which bin a sample lands in,
// which candidates each bin lists and in what order, and that a reused Bins holds nothing of
// the tile before.
#include "bins.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace strahler::tiling {
namespace {

using construction::World;
using geometry::Aabb;
using geometry::Vec2;

/// A raster of width × height samples dx × dy metres apart, row 0 north (y falling by row).
SampleGrid rasterGrid(int width, int height, double dx = 7.0, double dy = 5.0) {
  SampleGrid grid;
  grid.width = width;
  grid.height = height;
  for (int row = 0; row < height; ++row) {
    grid.rowSpacing.push_back(dx);
    for (int col = 0; col < width; ++col) {
      const Vec2 p{1000.0 + col * dx, 2000.0 - row * dy};
      grid.points.push_back(p);
      grid.bounds.add(p);
    }
  }
  return grid;
}

/// Bins of `grid` (`groups` runs by `rows` rows), reaching everywhere; `runBoxes` must outlive
/// them.
void resetBins(Bins& bins, const SampleGrid& grid, std::vector<Aabb>& runBoxes, int groups,
               int rows) {
  Bins::runBoxes(grid, runBoxes);
  bins.reset(grid, runBoxes, groups, rows, grid.bounds.expanded(1e6), true);
}

/// `n` random terrain discs over the box `area`, radii in [5, 40] m.
std::vector<primitives::TerrainPrimitive> randomTerrain(std::size_t n, const Aabb& area,
                                                        unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> x(area.min.x - 30.0, area.max.x + 30.0);
  std::uniform_real_distribution<double> y(area.min.y - 30.0, area.max.y + 30.0);
  std::uniform_real_distribution<double> radius(5.0, 40.0);
  std::vector<primitives::TerrainPrimitive> terrain(n);
  for (primitives::TerrainPrimitive& t : terrain) {
    t.center = {x(random), y(random)};
    t.radius = radius(random);
  }
  return terrain;
}

/// The ids whose disc meets bin (i, j)'s box, ascending: what every way of adding terrain must
/// list there.
std::vector<std::uint32_t> discsMeeting(const Bins& bins, const TerrainDiscs& discs, int i, int j) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t id = 0; id < discs.x.size(); ++id)
    if (squaredDistanceToBox(discs.center(id), bins.box(i, j)) <= discs.reach2[id])
      ids.push_back(id);
  return ids;
}

/// Bin (i, j)'s terrain list and keys as vectors.
std::vector<std::uint32_t> terrainOf(const Bins& bins, int i, int j) {
  const auto list = bins.terrain(bins.at(i, j));
  return {list.begin(), list.end()};
}

TEST(Bins, RunBoxesHoldEachRunOfLanesSamplesExactly) {
  const SampleGrid grid = rasterGrid(20, 3); // runs of 8, 8 and 4 samples per row
  std::vector<Aabb> boxes;
  Bins::runBoxes(grid, boxes);
  ASSERT_EQ(boxes.size(), 3u * 3u);
  for (int row = 0; row < grid.height; ++row)
    for (int col = 0; col < grid.width; col += base::kLanes) {
      Aabb expected;
      for (int k = col; k < std::min(grid.width, col + base::kLanes); ++k)
        expected.add(grid.points[static_cast<std::size_t>(row * grid.width + k)]);
      const Aabb& box = boxes[static_cast<std::size_t>(row * 3 + col / base::kLanes)];
      EXPECT_EQ(box.min, expected.min) << row << ", " << col;
      EXPECT_EQ(box.max, expected.max) << row << ", " << col;
    }
}

TEST(Bins, EverySampleLandsInTheBinOfItsRunGroupAndRowBand) {
  const SampleGrid grid = rasterGrid(37, 10); // 5 runs a row: bins of 2 runs × 3 rows
  std::vector<Aabb> runBoxes;
  Bins bins;
  resetBins(bins, grid, runBoxes, 2, 3);
  ASSERT_EQ(bins.perRow(), 3);
  ASSERT_EQ(bins.perColumn(), 4);
  ASSERT_EQ(bins.count(), 12u);
  EXPECT_TRUE(bins.monotone());
  std::vector<Aabb> expected(bins.count());
  for (int row = 0; row < grid.height; ++row)
    for (int col = 0; col < grid.width; ++col) {
      const std::size_t bin = bins.binOf(row, col);
      EXPECT_EQ(bin, bins.at(col / base::kLanes / 2, row / 3)) << row << ", " << col;
      expected[bin].add(grid.points[static_cast<std::size_t>(row * grid.width + col)]);
    }
  // A bin's box is the box of exactly its samples.
  for (int j = 0; j < bins.perColumn(); ++j)
    for (int i = 0; i < bins.perRow(); ++i) {
      EXPECT_EQ(bins.box(i, j).min, expected[bins.at(i, j)].min) << i << ", " << j;
      EXPECT_EQ(bins.box(i, j).max, expected[bins.at(i, j)].max) << i << ", " << j;
    }
}

TEST(Bins, BinsOfOneRunAreTheRunBoxes) {
  const SampleGrid grid = rasterGrid(20, 4);
  std::vector<Aabb> runBoxes;
  Bins bins;
  resetBins(bins, grid, runBoxes, 1, 1);
  ASSERT_EQ(bins.count(), runBoxes.size());
  for (int j = 0; j < bins.perColumn(); ++j)
    for (int i = 0; i < bins.perRow(); ++i)
      EXPECT_EQ(&bins.box(i, j), &runBoxes[bins.at(i, j)]);
}

TEST(Bins, RangeOfHoldsEveryBinMeetingTheBox) {
  const SampleGrid grid = rasterGrid(64, 40);
  std::vector<Aabb> runBoxes;
  Bins bins;
  resetBins(bins, grid, runBoxes, 2, 4);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(900.0, 1500.0), y(1750.0, 2100.0), side(0.0, 60.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec2 corner{x(random), y(random)};
    const Aabb box{corner, corner + Vec2{side(random), side(random)}};
    const Bins::Range range = bins.rangeOf(box);
    for (int j = 0; j < bins.perColumn(); ++j)
      for (int i = 0; i < bins.perRow(); ++i) {
        const bool inRange = i >= range.i0 && i < range.i1 && j >= range.j0 && j < range.j1;
        if (bins.box(i, j).intersects(box)) {
          EXPECT_TRUE(inRange) << "trial " << trial << ": bin " << i << ", " << j;
        }
      }
  }
}

TEST(Bins, EveryWayOfAddingTerrainListsExactlyTheDiscsMeetingEachBinAscending) {
  const SampleGrid grid = rasterGrid(48, 30);
  const std::vector<primitives::TerrainPrimitive> terrain = randomTerrain(300, grid.bounds, 11);
  const TerrainDiscs discs(terrain);
  const auto count = static_cast<std::uint32_t>(terrain.size());
  std::vector<Aabb> runBoxes;
  Bins byDisc, byBlock, byVisit;
  resetBins(byDisc, grid, runBoxes, 2, 5);
  resetBins(byBlock, grid, runBoxes, 2, 5);
  resetBins(byVisit, grid, runBoxes, 2, 5);
  const Bins::Range all{0, byBlock.perRow(), 0, byBlock.perColumn()};
  byBlock.addTerrainDiscs(all, discs, 0, count, construction::instructionSet());
  for (std::uint32_t id = 0; id < count; ++id) {
    const Aabb support = Aabb{discs.center(id), discs.center(id)}.expanded(terrain[id].radius);
    byDisc.addTerrainDisc(byDisc.rangeOf(support), discs, id);
    byVisit.forEachBin(
        support,
        [&](const Aabb& box) {
          return squaredDistanceToBox(discs.center(id), box) <= discs.reach2[id];
        },
        [&](std::size_t bin) { byVisit.addTerrain(bin, id, discs.keyY[id]); });
  }
  std::size_t listed = 0;
  for (int j = 0; j < byDisc.perColumn(); ++j)
    for (int i = 0; i < byDisc.perRow(); ++i) {
      const std::vector<std::uint32_t> expected = discsMeeting(byDisc, discs, i, j);
      listed += expected.size();
      EXPECT_EQ(terrainOf(byDisc, i, j), expected) << "addTerrainDisc, bin " << i << ", " << j;
      EXPECT_EQ(terrainOf(byBlock, i, j), expected) << "addTerrainDiscs, bin " << i << ", " << j;
      EXPECT_EQ(terrainOf(byVisit, i, j), expected) << "forEachBin, bin " << i << ", " << j;
      // Each id's key (its centre's y as a float) sits beside it.
      const std::size_t bin = byBlock.at(i, j);
      ASSERT_EQ(byBlock.terrainKeys(bin).size(), byBlock.terrain(bin).size());
      for (std::size_t k = 0; k < byBlock.terrain(bin).size(); ++k)
        EXPECT_EQ(byBlock.terrainKeys(bin)[k], discs.keyY[byBlock.terrain(bin)[k]]);
    }
  EXPECT_GT(listed, terrain.size()); // discs meet several bins: the test covers that
}

/// Runs of a river's curve: `n` boxes 10 m wide along a line from `from` by `step`.
std::vector<Aabb> riverRuns(Vec2 from, Vec2 step, int n) {
  std::vector<Aabb> runs;
  for (int c = 0; c < n; ++c) {
    const Vec2 a = from + step * c, b = from + step * (c + 1);
    Aabb box;
    box.add(a);
    box.add(b);
    runs.push_back(box.expanded(5.0));
  }
  return runs;
}

TEST(Bins, RiversInARangeGetEachBinNearARunWithTheSpanOfSuchRuns) {
  const SampleGrid grid = rasterGrid(64, 12); // 4 × 12 bins
  std::vector<Aabb> runBoxes;
  Bins bins;
  Bins::runBoxes(grid, runBoxes);
  bins.reset(grid, runBoxes, 2, 1, grid.bounds.expanded(1e6), false);
  // Two rivers crossing the tile diagonally, ids 3 and 7, added in ascending order.
  const std::vector<std::vector<Aabb>> rivers = {riverRuns({990.0, 2010.0}, {30.0, -8.0}, 16),
                                                 riverRuns({1010.0, 1880.0}, {25.0, 6.0}, 14)};
  const std::uint32_t ids[] = {3, 7};
  const double reach = 12.0;
  for (std::size_t r = 0; r < rivers.size(); ++r) {
    Aabb support; // as World::riverSupport(): the runs with the river's reach
    for (const Aabb& run : rivers[r])
      support.add(run.expanded(reach));
    const Bins::Range range = bins.rangeOf(support);
    ASSERT_LE(range.size(), kRangeBins);
    bins.addRiverInRange(range, ids[r], rivers[r], reach);
  }
  bins.finish();
  std::size_t listed = 0;
  for (int j = 0; j < bins.perColumn(); ++j)
    for (int i = 0; i < bins.perRow(); ++i) {
      std::vector<World::RiverCandidate> expected;
      for (std::size_t r = 0; r < rivers.size(); ++r) {
        World::RiverCandidate near{ids[r], 0, 0};
        for (std::uint32_t c = 0; c < rivers[r].size(); ++c)
          if (rivers[r][c].expanded(reach).intersects(bins.box(i, j))) {
            if (near.endChunk == 0)
              near.firstChunk = c;
            near.endChunk = c + 1;
          }
        if (near.endChunk > 0)
          expected.push_back(near);
      }
      const auto got = bins.rivers(bins.at(i, j));
      listed += got.size();
      ASSERT_EQ(got.size(), expected.size()) << "bin " << i << ", " << j;
      for (std::size_t k = 0; k < got.size(); ++k) {
        EXPECT_EQ(got[k].id, expected[k].id) << "bin " << i << ", " << j;
        EXPECT_EQ(got[k].firstChunk, expected[k].firstChunk) << "bin " << i << ", " << j;
        EXPECT_EQ(got[k].endChunk, expected[k].endChunk) << "bin " << i << ", " << j;
      }
    }
  EXPECT_GT(listed, 4u);
}

TEST(Bins, RunsOfOneRiverAddedToABinMergeIntoOneCandidate) {
  const SampleGrid grid = rasterGrid(32, 4);
  std::vector<Aabb> runBoxes;
  Bins bins;
  resetBins(bins, grid, runBoxes, 1, 1);
  bins.addRiverChunks(2, 5, 0, 1);
  bins.addRiverChunks(2, 5, 1, 2);
  bins.addRiverChunks(0, 5, 3, 4);
  bins.addRiverChunks(2, 5, 3, 4); // a gap of runs: the span covers it
  bins.addRiverChunks(2, 6, 2, 3);
  bins.finish();
  const auto two = bins.rivers(2);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].id, 5u);
  EXPECT_EQ(two[0].firstChunk, 0u);
  EXPECT_EQ(two[0].endChunk, 4u);
  EXPECT_EQ(two[1].id, 6u);
  EXPECT_EQ(two[1].firstChunk, 2u);
  EXPECT_EQ(two[1].endChunk, 3u);
  const auto zero = bins.rivers(0);
  ASSERT_EQ(zero.size(), 1u);
  EXPECT_EQ(zero[0].firstChunk, 3u);
  EXPECT_EQ(zero[0].endChunk, 4u);
  EXPECT_TRUE(bins.rivers(1).empty());
}

TEST(Bins, AReusedBinsHoldsNothingOfTheTileBefore) {
  const SampleGrid large = rasterGrid(80, 40), small = rasterGrid(24, 9, 3.0, 4.0);
  const std::vector<primitives::TerrainPrimitive> terrain = randomTerrain(200, large.bounds, 5);
  const TerrainDiscs discs(terrain);
  std::vector<Aabb> runBoxes;
  Bins reused;
  resetBins(reused, large, runBoxes, 2, 3);
  reused.addTerrainDiscs({0, reused.perRow(), 0, reused.perColumn()}, discs, 0, terrain.size(),
                         construction::instructionSet());
  for (std::size_t bin = 0; bin < reused.count(); ++bin)
    reused.addRiverChunks(bin, 9, 0, 2);
  reused.finish();
  // Reset for a smaller tile: empty lists, then the same lists as fresh bins get.
  std::vector<Aabb> smallRunBoxes;
  resetBins(reused, small, smallRunBoxes, 1, 2);
  reused.finish();
  ASSERT_EQ(reused.count(), 3u * 5u);
  for (std::size_t bin = 0; bin < reused.count(); ++bin) {
    EXPECT_TRUE(reused.terrain(bin).empty()) << bin;
    EXPECT_TRUE(reused.rivers(bin).empty()) << bin;
  }
  resetBins(reused, small, smallRunBoxes, 1, 2);
  Bins fresh;
  resetBins(fresh, small, smallRunBoxes, 1, 2);
  for (Bins* bins : {&reused, &fresh}) {
    bins->addTerrainDiscs({0, bins->perRow(), 0, bins->perColumn()}, discs, 0, terrain.size(),
                          construction::instructionSet());
    bins->addRiverChunks(4, 2, 1, 3);
    bins->finish();
  }
  for (int j = 0; j < fresh.perColumn(); ++j)
    for (int i = 0; i < fresh.perRow(); ++i) {
      EXPECT_EQ(terrainOf(reused, i, j), terrainOf(fresh, i, j)) << i << ", " << j;
      EXPECT_EQ(reused.rivers(fresh.at(i, j)).size(), fresh.rivers(fresh.at(i, j)).size());
    }
  EXPECT_EQ(reused.rivers(4).size(), 1u);
}

TEST(Bins, WhereColumnsAreNotMonotoneOnlyBinsMeetingTheReachAreVisited) {
  // A row folding back on itself (a tile wrapping half the globe): x rises then falls.
  SampleGrid grid;
  grid.width = 32;
  grid.height = 4;
  for (int row = 0; row < grid.height; ++row) {
    grid.rowSpacing.push_back(10.0);
    for (int col = 0; col < grid.width; ++col) {
      const Vec2 p{10.0 * (col < 16 ? col : 31 - col) + 3.0 * row, -10.0 * row};
      grid.points.push_back(p);
      grid.bounds.add(p);
    }
  }
  std::vector<Aabb> runBoxes;
  Bins::runBoxes(grid, runBoxes);
  const Aabb reach{{-1.0, -25.0}, {200.0, 1.0}}; // rows 0 to 2 only
  Bins bins;
  bins.reset(grid, runBoxes, 1, 1, reach, true);
  ASSERT_FALSE(bins.monotone());
  const Bins::Range range = bins.rangeOf(reach);
  EXPECT_EQ(range.size(), static_cast<int>(bins.count()));
  const Aabb support{{50.0, -30.0}, {75.0, 0.0}};
  std::vector<std::size_t> visited, expected;
  bins.forEachBin(
      support, [](const Aabb&) { return true; }, [&](std::size_t bin) { visited.push_back(bin); });
  for (int j = 0; j < bins.perColumn(); ++j)
    for (int i = 0; i < bins.perRow(); ++i)
      if (bins.box(i, j).intersects(reach) && bins.box(i, j).intersects(support))
        expected.push_back(bins.at(i, j));
  std::sort(visited.begin(), visited.end());
  EXPECT_EQ(visited, expected);
  EXPECT_FALSE(expected.empty());
  // Row 3 (y = −30) meets the support but not the reach: never visited.
  EXPECT_TRUE(std::none_of(visited.begin(), visited.end(),
                           [&](std::size_t bin) { return bin >= bins.at(0, 3); }));
}

} // namespace
} // namespace strahler::tiling
