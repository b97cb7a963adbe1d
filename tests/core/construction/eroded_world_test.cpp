// Erosion at generation (params erosionSteps > 0): the residual's lattice, determinism, and
// the rivers of the graph kept where and how deep they are.

#include "result_matchers.h"
#include "test_worlds.h"

#include "strahler/construction/world.h"
#include "strahler/construction/world_builder.h"
#include "strahler/quality/drainage.h"
#include "strahler/quality/river_profile.h"
#include "strahler/quality/world_raster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>

namespace strahler::construction {
namespace {

using geometry::Vec2;

input::WorldSpec erodedIslandSpec() {
  input::WorldSpec spec = test_support::defaultIslandSpec();
  spec.params.erosionSteps = 20;
  return spec;
}

const WorldData& erodedData() {
  static const WorldData data =
      test_support::valueOf(generateWorldData(erodedIslandSpec(), "eroded"));
  return data;
}

const World& erodedWorld() {
  static const World world(erodedData());
  return world;
}

TEST(ErodedWorld, TheResidualCoversTheLandOnTheGlobalLattice) {
  const ReliefResidual& r = erodedData().relief;
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r.spacing, 60.0);
  EXPECT_EQ(r.column0 % ReliefResidual::kChunk, 0);
  EXPECT_EQ(r.row0 % ReliefResidual::kChunk, 0);
  EXPECT_EQ(r.columns % ReliefResidual::kChunk, 0);
  EXPECT_EQ(r.rows % ReliefResidual::kChunk, 0);
  const geometry::Aabb land = erodedWorld().land().bounds();
  EXPECT_LE(r.column0 * r.spacing, land.min.x);
  EXPECT_LE(r.row0 * r.spacing, land.min.y);
  EXPECT_GE((r.column0 + r.columns) * r.spacing, land.max.x);
  EXPECT_GE((r.row0 + r.rows) * r.spacing, land.max.y);
  std::size_t lowered = 0, nonZero = 0;
  for (const std::int16_t q : r.quanta) {
    nonZero += q != 0;
    lowered += q < -100; // more than 10 m down
  }
  EXPECT_GT(nonZero, r.quanta.size() / 10);
  EXPECT_GT(lowered, nonZero / 4);
}

TEST(ErodedWorld, SameSpecGivesTheSameResidual) {
  const WorldData again = test_support::valueOf(generateWorldData(erodedIslandSpec(), "eroded"));
  EXPECT_EQ(again.relief, erodedData().relief);
}

TEST(ErodedWorld, WithoutErosionTheWorldIsTheTreeAlone) {
  // The same spec without erosion: the same primitives, no residual; the eroded world differs
  // from it off the rivers and nowhere on a river's floor.
  input::WorldSpec plain = erodedIslandSpec();
  plain.params.erosionSteps = 0;
  const WorldData data = test_support::valueOf(generateWorldData(plain, "plain"));
  EXPECT_TRUE(data.relief.empty());
  EXPECT_EQ(data.terrain, erodedData().terrain);
  EXPECT_EQ(data.rivers, erodedData().rivers);
  const World tree(data);
  const World& eroded = erodedWorld();
  int onFloors = 0, differ = 0;
  for (const primitives::RiverPrimitive& r : data.rivers)
    for (std::size_t k = 0; k < r.curve.size(); k += 5) {
      const Vec2 p = r.curve[k].position;
      const World::Evaluation e = eroded.evaluate(p, 2.0);
      if (e.rivers.w < 1.0)
        continue;
      ++onFloors;
      const double a = tree.height(p, 2.0), b = e.height;
      ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << p.x << ", " << p.y;
    }
  const geometry::Aabb box = eroded.land().bounds();
  for (int i = 0; i < 400; ++i) {
    const Vec2 p = box.min + Vec2{box.size().x * (0.1 + 0.002 * i), box.size().y * 0.5};
    differ += std::abs(tree.height(p, 30.0) - eroded.height(p, 30.0)) > 1.0;
  }
  EXPECT_GT(onFloors, 1000);
  EXPECT_GT(differ, 100);
}

TEST(ErodedWorld, RiversNeverRiseDownstream) {
  const World& world = erodedWorld();
  const quality::RiverProfileReport report = quality::checkRiversDescend(
      quality::riverCentrelines(world), [&](Vec2 p) { return world.height(p, 1.0); }, 5.0, 0.5);
  EXPECT_GT(report.samples, 10000u);
  EXPECT_EQ(report.violations, 0u) << "worst rise " << report.worstRise << " m";
}

TEST(ErodedWorld, BatchedHeightsEqualSingleHeights) {
  const World& world = erodedWorld();
  const geometry::Aabb box = world.land().bounds();
  for (const double spacing : {3.0, 30.0, 75.0, 250.0}) {
    std::vector<Vec2> points;
    for (int i = 0; i < 600; ++i)
      points.push_back(box.min +
                       Vec2{box.size().x * 0.3 + 7.3 * i, box.size().y * (0.2 + i / 1500.0)});
    std::vector<double> batched(points.size());
    world.heights(points, spacing, batched);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double single = world.height(points[i], spacing);
      ASSERT_EQ(std::memcmp(&batched[i], &single, sizeof single), 0)
          << "point " << i << " spacing " << spacing;
    }
  }
}

TEST(ErodedWorld, CoarseSamplesReadAPrefilteredResidual) {
  // At 480 m the residual comes from the pyramid's 480 m level: its variation between
  // neighbouring samples is far below the 60 m lattice's.
  const World& world = erodedWorld();
  const WorldData& data = erodedData();
  WorldData bare = data;
  bare.relief = {};
  const World tree(bare);
  const geometry::Aabb box = world.land().bounds();
  double fine = 0.0, coarse = 0.0;
  for (int i = 0; i < 200; ++i) {
    const Vec2 p = box.min + Vec2{box.size().x * 0.25 + 60.0 * i, box.size().y * 0.5};
    const Vec2 q = p + Vec2{60.0, 0.0};
    const auto delta = [&](Vec2 at, double s) { return world.height(at, s) - tree.height(at, s); };
    fine += std::abs(delta(q, 60.0) - delta(p, 60.0));
    coarse += std::abs(delta(q, 480.0) - delta(p, 480.0));
  }
  EXPECT_LT(coarse, 0.5 * fine);
}

} // namespace
} // namespace strahler::construction
