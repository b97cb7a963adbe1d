// The tectonic folds of a world with drawn mountains (issue 27, seed 002): plates from the
// mountains, folds in the terrain blend, bit-identical between tiles and the whole world.
#include "ci_environment.h"
#include "result_matchers.h"
#include "test_worlds.h"
#include "web_tiles.h"

#include "strahler/construction/world.h"
#include "strahler/construction/world_builder.h"
#include "strahler/quality/river_profile.h"
#include "strahler/quality/world_raster.h"
#include "strahler/simd/instruction_set.h"
#include "strahler/tiling/tile_evaluator.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <thread>

namespace strahler::construction {
namespace {

using geometry::Vec2;

/// Corsica's mountains as issue 27's fixture draws them: lon, lat, elevation.
struct Peak {
  double lon, lat, elevation;
};
constexpr Peak kPeaks[] = {{8.9456, 42.3797, 2706.0},  // Monte Cinto
                           {9.0567, 42.2178, 2622.0},  // Monte Rotondo
                           {9.1003, 42.1556, 2389.0},  // Monte d'Oro
                           {9.1306, 42.0711, 2352.0},  // Monte Renoso
                           {9.2028, 41.8553, 2134.0}}; // Monte Incudine

input::WorldSpec corsicaWithMountains() {
  input::WorldSpec spec = test_support::corsicaSpec();
  for (const Peak& p : kPeaks)
    spec.features.mountains.push_back(
        {{p.lon, p.lat}, spec.projection.forward({p.lon, p.lat}), p.elevation, std::nullopt});
  return spec;
}

/// Corsica generated with its drawn mountains.
const WorldData& foldedData() {
  static const WorldData data =
      test_support::valueOf(generateWorldData(corsicaWithMountains(), "folds"));
  return data;
}
const World& foldedWorld() {
  static const World world(foldedData());
  return world;
}
/// The same world data without the mountains: no folds.
const World& flatWorld() {
  static const World world = [] {
    WorldData data = foldedData();
    data.features.mountains.clear();
    return World(std::move(data));
  }();
  return world;
}

tiling::TileScheme webScheme() {
  const Vec2 c = foldedWorld().data().projectionCenter;
  return tiling::TileScheme::webMercator(geometry::LocalProjection(c.x, c.y));
}

/// Points on a regular grid over the land, `step` m apart.
std::vector<Vec2> landPoints(const World& world, double step) {
  std::vector<Vec2> points;
  const geometry::Aabb box = world.land().bounds();
  for (double y = box.min.y; y < box.max.y; y += step)
    for (double x = box.min.x; x < box.max.x; x += step)
      if (world.land().contains({x, y}))
        points.push_back({x, y});
  return points;
}

TEST(Folds, PlatesFromTheMountainsAreDeterministic) {
  const TectonicPlates* plates = foldedWorld().plates();
  ASSERT_NE(plates, nullptr);
  ASSERT_EQ(plates->plateOf.size(), std::size(kPeaks));
  // Built again from the same data (and on another thread): the same plates.
  TectonicPlates again;
  double seconds = 0.0;
  std::thread([&] {
    const auto start = std::chrono::steady_clock::now();
    const World world(foldedData());
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    again = *world.plates();
  }).join();
  EXPECT_EQ(again, *plates);
  const auto start = std::chrono::steady_clock::now();
  const World unfolded(flatWorld().data());
  std::printf("World built in %.3f s with the plates, %.3f s without\n", seconds,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  double area = 0.0;
  for (std::size_t k = 0; k < plates->plateOf.size(); ++k) {
    EXPECT_NEAR(geometry::length(plates->cellVelocity[k]), 1.0, 1e-12) << k;
    EXPECT_LT(plates->plateOf[k], plates->velocity.size());
    area += plates->cellAreaKm2[k];
    std::printf("mountain %zu: cell %.0f km², velocity (%.2f, %.2f), plate %u\n", k,
                plates->cellAreaKm2[k], plates->cellVelocity[k].x, plates->cellVelocity[k].y,
                plates->plateOf[k]);
  }
  EXPECT_NEAR(area, foldedWorld().data().areaKm2(), 0.05 * foldedWorld().data().areaKm2());
  // Five mountains along one chain: some cells merge, and at least two plates meet.
  EXPECT_GE(plates->velocity.size(), 2u);
  EXPECT_LT(plates->velocity.size(), std::size(kPeaks));
  EXPECT_EQ(plates->plateOf[0], 0u); // plates are numbered by their first mountain
  std::printf("%zu plates, merge threshold %.3f, fold reach %.0f m\n", plates->velocity.size(),
              plates->mergeThreshold, plates->foldReach);
}

TEST(Folds, WithoutMountainsTheWorldIsUnchanged) {
  // A world whose features hold no mountain (a ridge alone) has no plates and the same bits.
  WorldData data = foldedData();
  data.features.mountains.clear();
  data.features.ridges.push_back({{{9.0, 42.3}, {9.1, 42.2}}, {{0.0, 0.0}, {1000.0, 0.0}}, {}});
  const World ridgeOnly(std::move(data));
  EXPECT_EQ(ridgeOnly.plates(), nullptr);
  EXPECT_EQ(flatWorld().plates(), nullptr);
  EXPECT_EQ(flatWorld().foldStrength({0.0, 0.0}), 0.0);
  for (const Vec2 p : landPoints(flatWorld(), 3000.0)) {
    const double a = ridgeOnly.height(p, 20.0), b = flatWorld().height(p, 20.0);
    ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << p.x << ", " << p.y;
  }
}

/// Where the plates meet, computed here from the mountains alone: a point's cell is its
/// nearest mountain's (the plates' Voronoi partition), and its distance to the boundary with
/// mountain j's cell is at least its distance to their bisector, (|p − m_j|² − |p − m_i|²) /
/// (2 |m_j − m_i|). The plates (which cells merged) and their velocities are World's.
struct PlateGeometry {
  std::vector<Vec2> mountains;
  std::vector<std::uint32_t> plateOf;
  std::vector<Vec2> velocity;

  explicit PlateGeometry(const World& world) {
    for (const input::MountainFeature& m : world.data().features.mountains)
      mountains.push_back(m.position);
    plateOf = world.plates()->plateOf;
    velocity = world.plates()->velocity;
  }
  std::size_t cellOf(Vec2 p) const {
    std::size_t best = 0;
    for (std::size_t k = 1; k < mountains.size(); ++k)
      if (geometry::lengthSquared(p - mountains[k]) < geometry::lengthSquared(p - mountains[best]))
        best = k;
    return best;
  }
  double bisectorDistance(Vec2 p, std::size_t i, std::size_t j) const {
    return (geometry::lengthSquared(p - mountains[j]) - geometry::lengthSquared(p - mountains[i])) /
           (2.0 * geometry::length(mountains[j] - mountains[i]));
  }
  /// A lower bound of p's distance to any boundary of its plate with another plate.
  double plateBoundaryDistance(Vec2 p) const {
    const std::size_t i = cellOf(p);
    double d = 1e300;
    for (std::size_t j = 0; j < mountains.size(); ++j)
      if (plateOf[j] != plateOf[i])
        d = std::min(d, bisectorDistance(p, i, j));
    return d;
  }
};

TEST(Folds, FoldTheReliefNearConvergentBoundariesOnly) {
  const World& folded = foldedWorld();
  const World& flat = flatWorld();
  const PlateGeometry plates(folded);
  const double reach = folded.plates()->foldReach;
  ASSERT_GT(reach, 0.0);
  // Far from every plate boundary (beyond the reach, plus two of World's 500 m fold nodes for
  // its grid and its interpolation): not a bit changes.
  constexpr double kNodes = 2.0 * 1.5 * 500.0;
  std::size_t far = 0;
  for (const Vec2 p : landPoints(folded, 500.0)) {
    if (plates.plateBoundaryDistance(p) <= reach + kNodes)
      continue;
    const double a = folded.height(p, 30.0), b = flat.height(p, 30.0);
    ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << p.x << ", " << p.y;
    ++far;
  }
  // Across each boundary where the plates close in ((v_i − v_j) · n > 0.5, n the unit step from
  // mountain i towards j), 0.3 to 0.6 of the reach inside either plate and away from every other
  // boundary: the relief is folded there.
  std::size_t near = 0, changed = 0, boundaries = 0;
  double sum = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < plates.mountains.size(); ++i)
    for (std::size_t j = 0; j < plates.mountains.size(); ++j) {
      if (plates.plateOf[i] == plates.plateOf[j])
        continue;
      const Vec2 n = (plates.mountains[j] - plates.mountains[i]) /
                     geometry::length(plates.mountains[j] - plates.mountains[i]);
      const Vec2 closing = plates.velocity[plates.plateOf[i]] - plates.velocity[plates.plateOf[j]];
      const Vec2 middle = (plates.mountains[i] + plates.mountains[j]) * 0.5;
      bool meet = true; // no third mountain nearer the middle: their cells meet there
      for (std::size_t k = 0; k < plates.mountains.size(); ++k)
        meet = meet && (k == i || k == j ||
                        geometry::lengthSquared(middle - plates.mountains[k]) >
                            geometry::lengthSquared(middle - plates.mountains[i]));
      if (geometry::dot(closing, n) <= 0.5 || !meet)
        continue;
      ++boundaries;
      const Vec2 side{-n.y, n.x};
      for (double t = -0.6; t <= -0.3; t += 0.05)
        for (double s = -2000.0; s <= 2000.0; s += 250.0) {
          const Vec2 p = middle + n * (t * reach) + side * s;
          if (!folded.land().contains(p) || plates.cellOf(p) != i ||
              plates.plateBoundaryDistance(p) < 0.25 * reach + kNodes)
            continue;
          const double a = folded.height(p, 30.0), b = flat.height(p, 30.0);
          ++near;
          changed += a != b;
          sum += std::abs(a - b);
          worst = std::max(worst, std::abs(a - b));
        }
    }
  std::printf("fold reach %.0f m; %zu samples far from the plate boundaries; %zu near %zu "
              "converging boundaries (changed %zu), mean |fold| %.1f m, largest %.1f m\n",
              reach, far, near, boundaries, changed, sum / static_cast<double>(near), worst);
  EXPECT_GT(far, 1000u);
  ASSERT_GE(boundaries, 1u);
  ASSERT_GT(near, 20u);
  EXPECT_GT(changed, near * 9 / 10);
  // Tens of metres on average, at most a few hundred (TectonicFolds: amplitude and slope cap).
  EXPECT_GT(sum / static_cast<double>(near), 3.0);
  EXPECT_LT(worst, 600.0);
}

TEST(Folds, TilesEqualTheWholeWorldOnAnyThreadCount) {
  const World& world = foldedWorld();
  const tiling::TileEvaluator evaluator(world);
  const Peak& oro = kPeaks[2];
  std::size_t compared = 0, folded = 0;
  for (const int z : {10, 12, 14}) {
    std::vector<tiling::SampleGrid> grids;
    for (int d = 0; d < 3; ++d) {
      geometry::TileId tile = test_support::webTileAt(oro.lon, oro.lat, z);
      tile.x += d - 1;
      grids.push_back(z == 12 ? webScheme().meshGrid(tile, 64) : webScheme().rasterGrid(tile, 96));
    }
    std::vector<std::vector<double>> parallel(grids.size());
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < grids.size(); ++i)
      threads.emplace_back([&, i] { parallel[i] = evaluator.evaluate(grids[i]); });
    for (std::thread& t : threads)
      t.join();
    for (std::size_t i = 0; i < grids.size(); ++i) {
      const tiling::SampleGrid& grid = grids[i];
      EXPECT_EQ(evaluator.evaluate(grid), parallel[i]) << "zoom " << z;
      for (std::size_t k = 0; k < grid.points.size(); ++k) {
        const double slow = world.height(grid.points[k], grid.rowSpacing[k / grid.width]);
        ASSERT_EQ(std::memcmp(&parallel[i][k], &slow, sizeof slow), 0)
            << "zoom " << z << " tile " << i << " sample " << k;
        folded += world.foldStrength(grid.points[k]) > 0.0;
        ++compared;
      }
    }
  }
  EXPECT_GT(folded, compared / 4);
}

TEST(Folds, LanesEqualTheScalarPathOnEveryInstructionSet) {
  const World& world = foldedWorld();
  const simd::InstructionSet saved = simd::instructionSet();
  const Vec2 oro = world.data().features.mountains[2].position;
  std::vector<Vec2> row;
  for (int i = 0; i < 4000; ++i)
    row.push_back(oro + Vec2{-8000.0 + 4.0 * i, 3000.0 - 1.5 * i});
  int sets = 0;
  for (const auto set : {simd::InstructionSet::kBaseline, simd::InstructionSet::kAvx2,
                         simd::InstructionSet::kAvx512}) {
    if (!simd::useInstructionSet(set)) {
      test_support::noteMissingHardware("Folds.LanesEqualTheScalarPathOnEveryInstructionSet",
                                        set == simd::InstructionSet::kAvx2 ? "AVX2" : "AVX-512");
      continue;
    }
    ++sets;
    for (const double spacing : {4.0, 40.0}) {
      std::vector<double> lanes(row.size());
      world.heights(row, spacing, lanes);
      for (std::size_t k = 0; k < row.size(); ++k) {
        const double single = world.height(row[k], spacing);
        ASSERT_EQ(std::memcmp(&lanes[k], &single, sizeof single), 0)
            << "set " << static_cast<int>(set) << " spacing " << spacing << " point " << k;
      }
    }
  }
  simd::useInstructionSet(saved);
  EXPECT_GE(sets, 1);
}

TEST(Folds, NeighbouringTilesShareTheirEdges) {
  const tiling::TileEvaluator evaluator(foldedWorld());
  const Peak& rotondo = kPeaks[1];
  const int n = 32, w = n + 3;
  for (const int z : {10, 12, 14}) {
    const geometry::TileId a = test_support::webTileAt(rotondo.lon, rotondo.lat, z);
    const geometry::TileId east{a.z, a.x + 1, a.y};
    const std::vector<double> ha = evaluator.evaluate(webScheme().meshGrid(a, n));
    const std::vector<double> he = evaluator.evaluate(webScheme().meshGrid(east, n));
    for (int j = 0; j < w; ++j)
      ASSERT_EQ(std::memcmp(&ha[j * w + n + 1], &he[j * w + 1], sizeof(double)), 0)
          << "zoom " << z << " row " << j;
  }
}

TEST(Folds, DrainageHoldsWithFolds) {
  // The analyze figures without burning the rivers in (≥ 99.5 % drains) and the rivers'
  // profiles (0 violations), on 60 m cells (the default analysis takes 30 m; 60 m keeps the
  // test short and resolves every fold octave).
  const World& world = foldedWorld();
  const quality::DrainageReport folded = quality::checkDrainage(
      quality::rasterizeWorld(world, 60.0, 2, quality::RiverBurning::kNone), 1.0);
  const quality::DrainageReport flat = quality::checkDrainage(
      quality::rasterizeWorld(flatWorld(), 60.0, 2, quality::RiverBurning::kNone), 1.0);
  std::printf("draining without burning: %.4f with folds, %.4f without\n", folded.drainingFraction,
              flat.drainingFraction);
  EXPECT_GE(folded.drainingFraction, 0.995);
  const quality::RiverProfileReport rivers = quality::checkRiversDescend(
      quality::riverCentrelines(world), [&](Vec2 p) { return world.height(p, 1.0); }, 5.0, 0.5);
  EXPECT_GT(rivers.samples, 10000u);
  EXPECT_EQ(rivers.violations, 0u) << "worst rise " << rivers.worstRise << " m at "
                                   << rivers.worstAt.x << ", " << rivers.worstAt.y;
}

} // namespace
} // namespace strahler::construction
