#include "ci_environment.h"
#include "result_matchers.h"
#include "test_worlds.h"
#include "web_tiles.h"

#include "strahler/base/random.h"
#include "strahler/construction/world_builder.h"
#include "strahler/tiling/tile_evaluator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <thread>

namespace strahler::tiling {
namespace {

using geometry::Vec2;
using test_support::webTileAt;

const construction::World& islandWorld() {
  static const construction::World world(test_support::valueOf(
      construction::generateWorldData(test_support::defaultIslandSpec(), "tiles")));
  return world;
}

TileScheme localScheme() {
  return TileScheme::localFor(islandWorld().land().bounds());
}
TileScheme webScheme() {
  const Vec2 c = islandWorld().data().projectionCenter;
  return TileScheme::webMercator(geometry::LocalProjection(c.x, c.y));
}

TEST(TileEvaluator, RestrictedEvaluationEqualsTheWholeWorld) {
  const construction::World& world = islandWorld();
  const TileEvaluator evaluator(world);
  base::Rng rng(5);
  const TileScheme local = localScheme();
  const Vec2 c = world.data().projectionCenter;
  std::size_t compared = 0;
  for (int t = 0; t < 24; ++t) {
    const bool web = t % 2 == 1;
    const int z = web ? 9 + static_cast<int>(rng.below(6)) : 1 + static_cast<int>(rng.below(6));
    const TileScheme scheme = web ? webScheme() : local;
    geometry::TileId tile =
        web ? webTileAt(c.x + rng.uniform(-0.3, 0.3), c.y + rng.uniform(-0.15, 0.15), z)
            : geometry::TileId{z, rng.below(1u << z), rng.below(1u << z)};
    const SampleGrid grid = t % 3 == 0 ? scheme.meshGrid(tile, 16) : scheme.rasterGrid(tile, 32);
    TileStats stats;
    const std::vector<double> fast = evaluator.evaluate(grid, &stats);
    for (std::size_t k = 0; k < grid.points.size(); ++k) {
      const double slow = world.height(grid.points[k], grid.rowSpacing[k / grid.width]);
      ASSERT_NEAR(fast[k], slow, 1e-3) << "tile " << tile.z << "/" << tile.x << "/" << tile.y;
      ASSERT_EQ(std::memcmp(&fast[k], &slow, sizeof slow), 0) << "not bit-identical";
      ++compared;
    }
    EXPECT_LE(stats.terrainPrimitives, world.data().terrain.size());
  }
  EXPECT_GT(compared, 10000u);
}

TEST(TileEvaluator, TributaryTilesEqualTheWholeWorld) {
  // Tributaries (params.tributaryLevels) are carved per sample from regions of curves built per
  // thread: tiles still equal the whole world bit for bit, at zooms where every level shows.
  construction::WorldData data = islandWorld().data();
  data.params.tributaryLevels = 3;
  const construction::World world(std::move(data));
  const TileEvaluator evaluator(world);
  const Vec2 c = world.data().projectionCenter;
  std::size_t compared = 0, carved = 0;
  for (const int z : {12, 14, 16}) {
    const geometry::TileId tile = webTileAt(c.x, c.y, z);
    const SampleGrid grid =
        z == 14 ? webScheme().meshGrid(tile, 32) : webScheme().rasterGrid(tile, 64);
    const std::vector<double> fast = evaluator.evaluate(grid);
    const std::vector<double> plain = TileEvaluator(islandWorld()).evaluate(grid);
    for (std::size_t k = 0; k < grid.points.size(); ++k) {
      const double slow = world.height(grid.points[k], grid.rowSpacing[k / grid.width]);
      ASSERT_EQ(std::memcmp(&fast[k], &slow, sizeof slow), 0)
          << "tile " << z << "/" << tile.x << "/" << tile.y << " sample " << k;
      carved += fast[k] < plain[k];
      ++compared;
    }
  }
  EXPECT_GT(carved, compared / 10);
}

TEST(TileEvaluator, LowZoomTilesEqualTheWholeWorld) {
  // Samples kilometres apart: the island falls in a few bins holding every primitive.
  const construction::World& world = islandWorld();
  const TileEvaluator evaluator(world);
  const Vec2 c = world.data().projectionCenter;
  for (int z : {0, 3, 6}) {
    const SampleGrid grid = webScheme().rasterGrid(webTileAt(c.x, c.y, z), 256);
    const std::vector<double> fast = evaluator.evaluate(grid);
    int land = 0;
    for (std::size_t k = 0; k < grid.points.size(); ++k) {
      const double slow = world.height(grid.points[k], grid.rowSpacing[k / grid.width]);
      ASSERT_EQ(std::memcmp(&fast[k], &slow, sizeof slow), 0) << "zoom " << z << " sample " << k;
      land += slow > 0.0;
    }
    if (z > 0) { // at zoom 0 samples are 150 km apart and may all miss the island
      EXPECT_GT(land, 0) << "zoom " << z;
    }
  }
}

TEST(TileEvaluator, CoastalTilesEqualTheWholeWorld) {
  // Whole 256² tiles across the shore at the zooms where a bin spans hundreds of metres: the
  // shore distance comes from each bin's candidate segments, the land/sea side from one test
  // per bin where no boundary crosses it, rivers from the runs of their curves near each row.
  const construction::World& world = islandWorld();
  const TileEvaluator evaluator(world);
  const Vec2 c = world.data().projectionCenter;
  const double shelfFloor = -construction::CoastShape::kShelfDepth;
  for (int z : {8, 9, 10, 11}) {
    int land = 0, shelf = 0, mixedTiles = 0;
    for (int dx = 0; dx < 4; ++dx) {
      geometry::TileId tile = webTileAt(c.x, c.y, z);
      tile.x += dx * (1 << (z - 8)); // eastwards from the centre, into the sea
      const SampleGrid grid = webScheme().rasterGrid(tile, 256);
      const std::vector<double> fast = evaluator.evaluate(grid);
      int tileLand = 0, tileSea = 0;
      for (std::size_t k = 0; k < grid.points.size(); ++k) {
        const double slow = world.height(grid.points[k], grid.rowSpacing[k / grid.width]);
        ASSERT_EQ(std::memcmp(&fast[k], &slow, sizeof slow), 0)
            << "tile " << z << "/" << tile.x << "/" << tile.y << " sample " << k;
        tileLand += slow > 0.0;
        tileSea += slow < 0.0;
        shelf += slow < 0.0 && slow > 0.9 * shelfFloor; // on the shelf, near the shore
      }
      land += tileLand;
      mixedTiles += tileLand > 0 && tileSea > 0;
    }
    EXPECT_GT(land, 0) << "zoom " << z;
    EXPECT_GT(shelf, 0) << "zoom " << z;
    EXPECT_GT(mixedTiles, 0) << "zoom " << z;
  }
}

TEST(TileEvaluator, ScratchKeptOrReleasedBetweenTilesChangesNothing) {
  // A grid over kKeptScratchSamples samples releases the per-thread scratch; the tiles before
  // and after it, smaller and larger, evaluate as if each were the first.
  const construction::World& world = islandWorld();
  const Vec2 c = world.data().projectionCenter;
  const SampleGrid large = webScheme().rasterGrid(webTileAt(c.x, c.y, 10), 600);
  const SampleGrid small = webScheme().rasterGrid(webTileAt(c.x + 0.02, c.y, 12), 64);
  const std::vector<double> largeFirst = TileEvaluator(world).evaluate(large);
  const TileEvaluator evaluator(world);
  const std::vector<double> smallFirst = evaluator.evaluate(small);
  EXPECT_EQ(evaluator.evaluate(large), largeFirst);
  EXPECT_EQ(evaluator.evaluate(small), smallFirst);
  EXPECT_EQ(evaluator.evaluate(large), largeFirst);
  for (std::size_t k = 0; k < large.points.size(); k += 997)
    ASSERT_EQ(largeFirst[k], world.height(large.points[k], large.rowSpacing[k / large.width]));
}

TEST(TileEvaluator, SmallTilesGatherFewPrimitives) {
  const TileEvaluator evaluator(islandWorld());
  const TileScheme s = localScheme();
  TileStats stats;
  const int z = 7;
  evaluator.evaluate(s.rasterGrid({z, 64, 64}, 64), &stats); // near the centre
  EXPECT_GT(stats.terrainPrimitives, 0u);
  EXPECT_LT(stats.terrainPrimitives, islandWorld().data().terrain.size() / 20);
}

TEST(TileEvaluator, SeaAndOutsideTilesAreValidDepths) {
  const TileEvaluator evaluator(islandWorld());
  const TileScheme web = webScheme();
  for (const geometry::TileId tile :
       {geometry::TileId{0, 0, 0}, geometry::TileId{8, 0, 0}, geometry::TileId{12, 100, 3000}}) {
    const SampleGrid grid = web.rasterGrid(tile, 16);
    for (double h : evaluator.evaluate(grid)) {
      ASSERT_TRUE(std::isfinite(h));
      ASSERT_LE(h, 2000.0);
    }
  }
  // A tile far out at sea is entirely below sea level.
  const Vec2 c = islandWorld().data().projectionCenter;
  for (double h : evaluator.evaluate(web.rasterGrid(webTileAt(c.x + 3.0, c.y, 10), 16)))
    ASSERT_LT(h, -100.0);
}

TEST(TileEvaluator, MeshNeighboursShareEdgeHeightsBitForBit) {
  const TileEvaluator evaluator(islandWorld());
  const TileScheme s = localScheme();
  const int z = 6, n = 32, w = n + 3;
  const geometry::TileId a{z, 30, 31}, east{z, 31, 31};
  const std::vector<double> ha = evaluator.evaluate(s.meshGrid(a, n));
  const std::vector<double> he = evaluator.evaluate(s.meshGrid(east, n));
  for (int j = 0; j < w; ++j)
    ASSERT_EQ(std::memcmp(&ha[j * w + n + 1], &he[j * w + 1], sizeof(double)), 0) << j;
}

TEST(TileEvaluator, ParentAndChildrenAgreeWithinTheFadedOctaves) {
  const TileEvaluator evaluator(islandWorld());
  const TileScheme s = localScheme();
  const int z = 5, n = 16;
  const geometry::TileId parent{z, 15, 16};
  const std::vector<double> hp = evaluator.evaluate(s.meshGrid(parent, n));
  const std::vector<double> hc = evaluator.evaluate(s.meshGrid({z + 1, 30, 33}, n)); // its SW child
  // The child's vertex (2i, 2j) is the parent's vertex (i, j): same point, finer spacing.
  double worst = 0.0;
  for (int j = 0; j <= n / 2; ++j)
    for (int i = 0; i <= n / 2; ++i)
      worst = std::max(
          worst, std::abs(hp[(j + 1) * (n + 3) + i + 1] - hc[(2 * j + 1) * (n + 3) + 2 * i + 1]));
  // Only octaves between 2 and 4 parent spacings differ, and the rivers' floors (the child's
  // banks start up to 0.375 spacings nearer a river): at most 0.35 parent spacings.
  const double spacing = s.localBounds(parent).size().x / n;
  EXPECT_LT(worst, 0.35 * spacing) << "spacing " << spacing;
}

TEST(TileEvaluator, SameTilesOnAnyThreadCount) {
  const TileEvaluator evaluator(islandWorld());
  const TileScheme s = localScheme();
  std::vector<geometry::TileId> tiles;
  for (int i = 0; i < 8; ++i)
    tiles.push_back({5, 12 + i, 14 + i % 3});
  std::vector<std::vector<double>> sequential;
  for (const geometry::TileId& t : tiles)
    sequential.push_back(evaluator.evaluate(s.rasterGrid(t, 32)));
  std::vector<std::vector<double>> parallel(tiles.size());
  std::vector<std::thread> threads;
  for (int worker = 0; worker < 4; ++worker)
    threads.emplace_back([&, worker] {
      for (std::size_t i = static_cast<std::size_t>(worker); i < tiles.size(); i += 4)
        parallel[i] = evaluator.evaluate(s.rasterGrid(tiles[i], 32));
    });
  for (std::thread& t : threads)
    t.join();
  EXPECT_EQ(parallel, sequential);
}

/// Restores the instruction set a test changed.
struct InstructionSetGuard {
  simd::InstructionSet saved = simd::instructionSet();
  ~InstructionSetGuard() { simd::useInstructionSet(saved); }
};

TEST(TileEvaluator, SameBitsOnEveryInstructionSet) {
  const InstructionSetGuard guard;
  const construction::World& world = islandWorld();
  const TileEvaluator evaluator(world);
  const Vec2 c = world.data().projectionCenter;
  std::vector<SampleGrid> grids;
  for (int z : {0, 9, 12, 15, 18})
    grids.push_back(webScheme().rasterGrid(webTileAt(c.x + 0.05, c.y - 0.03, z), 40));
  grids.push_back(localScheme().meshGrid({4, 7, 9}, 20));
  ASSERT_TRUE(simd::useInstructionSet(simd::InstructionSet::kBaseline));
  std::vector<std::vector<double>> baseline;
  for (const SampleGrid& g : grids)
    baseline.push_back(evaluator.evaluate(g));
  int compared = 0;
  for (auto set : {simd::InstructionSet::kAvx2, simd::InstructionSet::kAvx512}) {
    if (!simd::useInstructionSet(set)) {
      test_support::noteMissingHardware("TileEvaluator (instruction sets)",
                                        set == simd::InstructionSet::kAvx2 ? "AVX2" : "AVX-512");
      continue;
    }
    for (std::size_t i = 0; i < grids.size(); ++i) {
      const std::vector<double> heights = evaluator.evaluate(grids[i]);
      ASSERT_EQ(heights.size(), baseline[i].size());
      ASSERT_EQ(std::memcmp(heights.data(), baseline[i].data(), heights.size() * sizeof(double)), 0)
          << "grid " << i << " differs on instruction set " << static_cast<int>(set);
      ++compared;
    }
  }
  if (compared == 0)
    GTEST_SKIP() << "this CPU has neither AVX2 nor AVX-512";
}

} // namespace
} // namespace strahler::tiling
