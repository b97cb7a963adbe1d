#include "test_worlds.h"

#include "strahler/base/random.h"
#include "strahler/construction/world.h"
#include "strahler/construction/world_builder.h"
#include "strahler/geometry/distance.h"
#include "strahler/quality/drainage.h"
#include "strahler/quality/river_profile.h"
#include "strahler/quality/world_raster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

namespace strahler::construction {
namespace {

using geometry::Vec2;

/// The default island's data with `levels` tributary levels (generated once: the levels only
/// change evaluation, so both worlds share the same vector description).
const WorldData& islandData() {
  static const WorldData data = [] {
    input::WorldSpec spec = test_support::defaultIslandSpec();
    auto generated = generateWorldData(spec, "test");
    EXPECT_TRUE(generated.ok()) << generated.error().message;
    return std::move(generated).value();
  }();
  return data;
}

const World& islandWith(int levels) {
  static std::unique_ptr<World> worlds[4];
  if (!worlds[levels]) {
    WorldData data = islandData();
    data.params.tributaryLevels = levels;
    worlds[levels] = std::make_unique<World>(std::move(data));
  }
  return *worlds[levels];
}

/// A 30 m grid of points over the middle of the island.
std::vector<Vec2> middleGrid(int side) {
  const geometry::Aabb box = islandWith(0).land().bounds();
  const Vec2 c = (box.min + box.max) * 0.5;
  std::vector<Vec2> points;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i)
      points.push_back(c + Vec2{(i - side / 2) * 30.0, (j - side / 2) * 30.0});
  return points;
}

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(Tributaries, CarveValleysIntoTheLandAndNeverRaiseIt) {
  const World& plain = islandWith(0);
  const World& carved = islandWith(3);
  std::size_t land = 0, lowered = 0;
  for (const Vec2 p : middleGrid(120)) {
    const double before = plain.height(p, 15.0), after = carved.height(p, 15.0);
    ASSERT_LE(after, before) << p.x << ", " << p.y;
    if (before > 0.0)
      ++land;
    if (after < before - 1.0)
      ++lowered;
  }
  ASSERT_GT(land, 10000u);
  // Valleys of every level cut a good part of the land (not a few pits).
  EXPECT_GT(lowered, land / 5) << lowered << " of " << land;
}

TEST(Tributaries, ZeroLevelsLeaveTheWorldAsItWas) {
  // Inland (beyond the coast's band) a world's height is the tree C(B, U) unless tributaries
  // carve it: with zero levels every point is the tree's, with three some are not (so the
  // check can tell).
  const World& plain = islandWith(0);
  const World& carved = islandWith(3);
  std::size_t inland = 0, carvedPoints = 0;
  for (const Vec2 p : middleGrid(40)) {
    if (!plain.land().contains(p) || plain.land().distanceToBoundary(p, 1000.0) < 1000.0)
      continue;
    ++inland;
    const World::Evaluation e = plain.evaluate(p, 15.0);
    ASSERT_TRUE(sameBits(e.height, e.tree)) << p.x << ", " << p.y;
    const World::Evaluation c = carved.evaluate(p, 15.0);
    carvedPoints += !sameBits(c.height, c.tree);
  }
  EXPECT_GT(inland, 100u);
  EXPECT_GT(carvedPoints, 0u);
}

TEST(Tributaries, FadeOutWhereSamplesAreCoarserThanTheirCells) {
  // The coarsest level (400 m cells) is gone at 200 m spacing and beyond.
  for (const Vec2 p : middleGrid(40))
    ASSERT_TRUE(sameBits(islandWith(3).height(p, 200.0), islandWith(0).height(p, 200.0)));
  // One level is one level: at 30 m, levels 1..3 differ from each other somewhere.
  std::size_t differ = 0;
  for (const Vec2 p : middleGrid(40))
    differ += !sameBits(islandWith(1).height(p, 30.0), islandWith(3).height(p, 30.0));
  EXPECT_GT(differ, 0u);
}

TEST(Tributaries, SameBitsInAnyOrderOnAnyThread) {
  // Each region of curves is built on first use and kept per thread: the heights must not
  // depend on which points came first, nor on the thread.
  const World& world = islandWith(3);
  std::vector<Vec2> points = middleGrid(60);
  base::Rng rng(3);
  for (std::size_t i = points.size(); i > 1; --i)
    std::swap(points[i - 1], points[rng.below(static_cast<std::uint32_t>(i))]);
  std::vector<double> forward(points.size()), backward(points.size()), other(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    forward[i] = world.height(points[i], 20.0);
  std::thread([&] {
    for (std::size_t i = points.size(); i-- > 0;)
      backward[i] = world.height(points[i], 20.0);
    world.heights(points, 20.0, other); // runs of lanes
  }).join();
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_TRUE(sameBits(forward[i], backward[i])) << i;
    ASSERT_TRUE(sameBits(forward[i], other[i])) << i;
  }
}

TEST(Tributaries, TheCarvedLandStillDrains) {
  // 60 m cells over the whole island, the graph's rivers burnt in as for every world: the
  // tributaries' channels fall all the way to their junctions, so they add no pits.
  const quality::DrainageReport plain =
      quality::checkDrainage(quality::rasterizeWorld(islandWith(0), 60.0, 2), 1.0);
  const quality::DrainageReport carved =
      quality::checkDrainage(quality::rasterizeWorld(islandWith(3), 60.0, 2), 1.0);
  EXPECT_GT(carved.landCells, 200000u);
  EXPECT_GE(carved.drainingFraction, plain.drainingFraction - 0.005)
      << carved.pits << " pits, largest " << carved.largestUndrainedAreaKm2 << " km²";
}

/// The default island generated with tributaries (its rivers wander).
const WorldData& wanderingIslandData() {
  static const WorldData data = [] {
    input::WorldSpec spec = test_support::defaultIslandSpec();
    spec.params.tributaryLevels = 3;
    auto generated = generateWorldData(spec, "test");
    EXPECT_TRUE(generated.ok()) << generated.error().message;
    return std::move(generated).value();
  }();
  return data;
}

TEST(Tributaries, RiversWanderUnderThem) {
  // With tributaries the graph's rivers wander at two scales, straight (B) ones too; without,
  // a B river keeps close to its edge. Ends (the nodes) stay where they were.
  const WorldData& wandering = wanderingIslandData();
  const WorldData& plain = islandData();
  ASSERT_EQ(wandering.rivers.size(), plain.rivers.size());
  const auto offset = [](const primitives::RiverPrimitive& r) {
    const Vec2 a = r.curve.front().position, b = r.curve.back().position;
    double most = 0.0;
    for (const primitives::CurvePoint& q : r.curve)
      most = std::max(most, geometry::pointSegmentDistance(q.position, a, b));
    return most;
  };
  double plainSum = 0.0, wanderingSum = 0.0;
  std::size_t straight = 0;
  for (std::size_t i = 0; i < plain.rivers.size(); ++i) {
    const primitives::RiverPrimitive& before = plain.rivers[i];
    const primitives::RiverPrimitive& after = wandering.rivers[i];
    ASSERT_EQ(before.curve.front().position, after.curve.front().position);
    ASSERT_EQ(before.curve.back().position, after.curve.back().position);
    if (before.type != primitives::RiverType::kStraight || before.curve.size() < 10)
      continue;
    ++straight;
    plainSum += offset(before);
    wanderingSum += offset(after);
  }
  ASSERT_GT(straight, 50u);
  const double plainMean = plainSum / double(straight);
  const double wanderingMean = wanderingSum / double(straight);
  EXPECT_GT(wanderingMean, plainMean + 20.0) << plainMean << " m against " << wanderingMean << " m";
}

TEST(Tributaries, RiversNeverRiseDownstream) {
  // Neither the wandering curves (faded over a wavelength at the nodes, so a section does not
  // cross its parent's floor) nor the tributaries' valleys (never below the water beside
  // their parent) make a river's bed rise downstream.
  const World world(wanderingIslandData());
  const quality::RiverProfileReport report = quality::checkRiversDescend(
      quality::riverCentrelines(world), [&](Vec2 p) { return world.height(p, 1.0); }, 5.0, 0.5);
  EXPECT_GT(report.samples, 10000u);
  EXPECT_EQ(report.violations, 0u) << "worst rise " << report.worstRise << " m at "
                                   << report.worstAt.x << ", " << report.worstAt.y;
}

} // namespace
} // namespace strahler::construction
