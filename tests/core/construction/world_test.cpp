#include "result_matchers.h"
#include "test_worlds.h"

#include "strahler/base/random.h"
#include "strahler/construction/world.h"
#include "strahler/construction/world_builder.h"
#include "strahler/geometry/distance.h"
#include "strahler/primitives/river_primitives.h"
#include "strahler/quality/drainage.h"
#include "strahler/quality/flow_field.h"
#include "strahler/quality/river_agreement.h"
#include "strahler/quality/river_profile.h"
#include "strahler/quality/world_raster.h"
#include "strahler/simd/lanes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

namespace strahler::construction {
namespace {

using geometry::Vec2;

/// The default island, generated once for the whole suite.
const World& defaultWorld() {
  static const std::unique_ptr<World> world = [] {
    auto data = generateWorldData(test_support::defaultIslandSpec(), "test");
    EXPECT_TRUE(data.ok()) << data.error().message;
    return std::make_unique<World>(test_support::valueOf(std::move(data)));
  }();
  return *world;
}

/// One gully octave at lattice point q with stripes across the unit vector n, written out
/// plainly (evaluation_kernels.inc, gullyOctave): its value and its derivative along n.
std::pair<double, double> referenceGully(std::uint32_t seed, Vec2 q, Vec2 n) {
  const double x0 = std::floor(q.x), y0 = std::floor(q.y);
  const double fx = q.x - x0, fy = q.y - y0;
  const auto fade = [](double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); };
  const double u = fade(fx), v = fade(fy);
  double value = 0.0, slope = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const auto cx = static_cast<std::uint32_t>(static_cast<std::int32_t>(x0) + i);
      const auto cy = static_cast<std::uint32_t>(static_cast<std::int32_t>(y0) + j);
      std::uint32_t h = (cx * 0x8da6b343u) ^ (cy * 0xd8163841u) ^ seed;
      h ^= h >> 15;
      h *= 0x2c1b3c6du;
      h ^= h >> 13;
      const double phase =
          2.0 * ((fx - i) * n.x + (fy - j) * n.y) + static_cast<double>(h >> 8) / 16777216.0;
      const double s = phase - std::nearbyint(phase);
      const double weight = (i ? u : 1.0 - u) * (j ? v : 1.0 - v);
      value += weight * (2.0 / 3.0 - 8.0 * s * s);
      slope += weight * -16.0 * s;
    }
  return {value, slope};
}

/// B(T…) at p written out plainly from its definition (world.h, evaluation_kernels.inc),
/// every primitive visited: the reference for the vectorised evaluator.
Sample referenceTerrain(const World& world, Vec2 p, double spacing) {
  const noise::LatticeNoise noise(world.data().params.seed ^ 0x746572726e6full);
  const auto gullySeed =
      static_cast<std::uint32_t>(base::mixHash(world.data().params.seed, 0x67756c6c79ull));
  double weight = 0.0, weightedHeight = 0.0, amplitude = 0.0, roughness = 0.0;
  Vec2 weightGradient, heightGradient, planeGradient; // Σ ∇w_i, Σ ∇w_i h_i, Σ w_i s_i
  int count = 0;
  for (const primitives::TerrainPrimitive& t : world.data().terrain) {
    const double r2 = t.radius * t.radius;
    const double w = primitives::falloff(lengthSquared(p - t.center), r2);
    if (w <= 0.0)
      continue;
    ++count;
    const double plane = t.elevation + dot(t.slope, p - t.center);
    weight += w;
    weightedHeight += w * plane;
    amplitude += w * t.amplitude;
    roughness += w * std::min(t.roughness, World::kMaxRoughness);
    const Vec2 gradient = (p - t.center) * (-4.0 * (1.0 - lengthSquared(p - t.center) / r2) / r2);
    weightGradient = weightGradient + gradient;
    heightGradient = heightGradient + gradient * plane;
    planeGradient = planeGradient + t.slope * w;
  }
  if (count == 0)
    return {};
  const double base = weightedHeight / weight;
  Vec2 slope = (heightGradient - weightGradient * base + planeGradient) * (1.0 / weight);
  const double g = roughness / weight;
  double octave = amplitude / weight, sum = 0.0, flanks = 1.0;
  for (int k = 1; k < NoiseOctaves::kOctaves; ++k) {
    const double wavelength = NoiseOctaves::kLongest / std::ldexp(1.0, k);
    const double fade = octaveFade(wavelength, spacing);
    octave *= g;
    if (fade <= 0.0 || octave < 1e-3)
      break;
    const Vec2 q{p.x / wavelength + 37.1 * k, p.y / wavelength - 11.7 * k};
    if (k < 2 || k > 6) { // gradient noise
      sum += fade * octave * noise.at(q);
      continue;
    }
    const double steepness = length(slope);
    const Vec2 across = steepness > 1e-12 ? perpendicular(slope) * (1.0 / steepness) : Vec2{};
    const auto [value, rise] = referenceGully(gullySeed, q, across);
    const double depth = std::min(fade * octave, 0.035 * steepness * wavelength) * flanks;
    sum += depth * value;
    flanks *= std::clamp((value + 4.0 / 3.0) * 2.0, 0.0, 1.0);
    slope = slope + across * (depth * rise * 2.0 / wavelength);
  }
  return {base + sum, weight / count};
}

/// U(R…) at p sampled `spacing` apart over terrain height `terrain` from its definition, every
/// segment of every river visited.
Sample referenceRivers(const World& world, Vec2 p, double spacing, double terrain) {
  Sample best;
  for (const primitives::RiverPrimitive& r : world.data().rivers) {
    double nearest = std::numeric_limits<double>::infinity(), elevation = 0.0, along = 0.0;
    for (std::size_t k = 0; k + 1 < r.curve.size(); ++k) {
      const Vec2 a = r.curve[k].position, b = r.curve[k + 1].position;
      const Vec2 q = geometry::closestPointOnSegment(p, a, b);
      const double d = distance(p, q);
      if (d >= nearest)
        continue;
      const double t = distance(a, b) > 0.0 ? distance(a, q) / distance(a, b) : 0.0;
      nearest = d;
      elevation = r.curve[k].elevation + (r.curve[k + 1].elevation - r.curve[k].elevation) * t;
      along = (static_cast<double>(k) + t) / static_cast<double>(r.curve.size() - 1);
    }
    const double width = r.widthUp + (r.widthDown - r.widthUp) * along;
    const double depth = r.depthUp + (r.depthDown - r.depthUp) * along;
    const double minReach =
        std::min(primitives::valleyMinReach(r.type, r.widthUp, r.widthDown), r.radius);
    const double floor = primitives::riverFloor(minReach, spacing);
    const double reach = primitives::valleyReach(minReach, r.radius, terrain - elevation);
    const double fade = primitives::riverFade(r.radius, spacing);
    const double w =
        nearest < reach ? primitives::riverWeight(width, reach, nearest, floor, fade) : 0.0;
    if (w <= 0.0)
      continue;
    const Sample s{elevation + primitives::riverProfile(r.type, width, depth, nearest, floor), w};
    best = best.w > 0.0 ? uniteByCut(best, s, terrain) : s;
  }
  return best;
}

TEST(World, EvaluationMatchesThePlainDefinition) {
  const World& world = defaultWorld();
  const geometry::Aabb box = world.land().bounds();
  base::Rng rng(11);
  int onRivers = 0;
  for (int i = 0; i < 400; ++i) {
    // Half the points next to a river curve, the others anywhere on the island's box.
    Vec2 p{rng.uniform(box.min.x, box.max.x), rng.uniform(box.min.y, box.max.y)};
    if (i % 2 == 0) {
      const auto& rivers = world.data().rivers;
      const primitives::RiverPrimitive& r =
          rivers[rng.below(static_cast<std::uint32_t>(rivers.size()))];
      p = r.curve[rng.below(static_cast<std::uint32_t>(r.curve.size()))].position +
          Vec2{rng.uniform(-60.0, 60.0), rng.uniform(-60.0, 60.0)};
    }
    const double spacing = std::ldexp(1.0, static_cast<int>(rng.below(10))) * 0.5;
    const World::Evaluation e = world.evaluate(p, spacing);
    const Sample terrain = referenceTerrain(world, p, spacing);
    const Sample rivers = referenceRivers(world, p, spacing, e.terrain.h);
    EXPECT_NEAR(e.terrain.h, terrain.h, 1e-9) << p.x << ", " << p.y << " spacing " << spacing;
    EXPECT_NEAR(e.terrain.w, terrain.w, 1e-12);
    EXPECT_NEAR(e.rivers.h, rivers.h, 1e-9) << p.x << ", " << p.y;
    EXPECT_NEAR(e.rivers.w, rivers.w, 1e-12);
    onRivers += rivers.w > 0.0;
  }
  EXPECT_GT(onRivers, 150);
}

TEST(World, BatchedHeightsEqualSingleHeights) {
  const World& world = defaultWorld();
  const geometry::Aabb box = world.land().bounds();
  std::vector<Vec2> points;
  for (int i = 0; i < 1000; ++i) // rows of neighbours, crossing index cells now and then
    points.push_back(box.min +
                     Vec2{box.size().x * 0.3 + 7.3 * i, box.size().y * (0.2 + i / 2000.0)});
  std::vector<double> batched(points.size());
  world.heights(points, 3.0, batched);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double single = world.height(points[i], 3.0);
    ASSERT_EQ(std::memcmp(&batched[i], &single, sizeof single), 0) << "point " << i;
  }
}

TEST(World, PairedRunsEqualSingleHeights) {
  // Two runs sharing every terrain candidate, each with its own spacing and rivers: the
  // terrain sums of both in one pass must give each point its own height bit for bit.
  const World& world = defaultWorld();
  const geometry::Aabb box = world.land().bounds();
  std::vector<std::uint32_t> terrain(world.data().terrain.size());
  for (std::uint32_t i = 0; i < terrain.size(); ++i)
    terrain[i] = i;
  std::vector<World::RiverCandidate> rivers;
  for (std::uint32_t i = 0; i < world.data().rivers.size(); ++i)
    rivers.push_back(world.wholeRiver(base::PrimitiveId(i)));
  constexpr std::size_t kRun = simd::kLanes;
  for (int pair = 0; pair < 40; ++pair) {
    std::vector<Vec2> first, second;
    for (std::size_t l = 0; l < kRun; ++l) {
      const Vec2 p =
          box.min + Vec2{box.size().x * (0.05 + pair / 45.0) + 37.0 * static_cast<double>(l),
                         box.size().y * (0.1 + pair / 50.0)};
      first.push_back(p);
      second.push_back(p + Vec2{3.0, -41.0});
    }
    std::vector<double> a(kRun), b(kRun);
    world.heightsFrom({first, 2.0, rivers, a}, {second, 6.0, rivers, b}, terrain, {});
    for (std::size_t l = 0; l < kRun; ++l) {
      const double singleA = world.height(first[l], 2.0), singleB = world.height(second[l], 6.0);
      ASSERT_EQ(std::memcmp(&a[l], &singleA, sizeof singleA), 0)
          << "pair " << pair << " lane " << l;
      ASSERT_EQ(std::memcmp(&b[l], &singleB, sizeof singleB), 0)
          << "pair " << pair << " lane " << l;
    }
  }
}

TEST(World, RiversNeverRiseDownstream) {
  const World& world = defaultWorld();
  const auto centrelines = quality::riverCentrelines(world);
  const quality::RiverProfileReport report = quality::checkRiversDescend(
      centrelines, [&](Vec2 p) { return world.height(p, 1.0); }, 5.0, 0.5);
  EXPECT_GT(report.samples, 10000u);
  EXPECT_EQ(report.violations, 0u) << "worst rise " << report.worstRise << " m at "
                                   << report.worstAt.x << ", " << report.worstAt.y;
}

// Sibling channels run to one node side by side: on Mallorca (seed 42) at generator 8 two
// sources 80 m apart ran 1 km to their mouth, one meandering across the other's straight
// course, whose samples took the lower bed where they crossed (136 samples rose, up to 1.9 m).
// Every channel now keeps clear of its siblings, its inflows and the section below it.
TEST(World, MallorcasSiblingChannelsNeverMakeARiverRise) {
  auto data = generateWorldData(test_support::mallorcaSpec(42), "test");
  ASSERT_TRUE(data.ok()) << data.error().message;
  const World world(test_support::valueOf(std::move(data)));
  const quality::RiverProfileReport report = quality::checkRiversDescend(
      quality::riverCentrelines(world), [&](Vec2 p) { return world.height(p, 1.0); }, 5.0, 0.5);
  EXPECT_GT(report.samples, 500000u);
  EXPECT_EQ(report.violations, 0u) << "worst rise " << report.worstRise << " m at "
                                   << report.worstAt.x << ", " << report.worstAt.y;
}

// Near the shore the coast's cap holds heights below the shore distance, so a curve that
// meandered up to a fjord's shore dipped there (Iceland: a bed 55 m up, 18 m from the shore,
// read a 37 m dip). Curves keep half of δ from Γ, or as much as their edge does.
TEST(World, RiverCurvesKeepClearOfTheShore) {
  const World& world = defaultWorld();
  const double clearance = 0.5 * world.data().params.delta;
  std::size_t points = 0, near = 0;
  for (const primitives::RiverPrimitive& r : world.data().rivers) {
    const Vec2 a = r.curve.front().position, b = r.curve.back().position;
    for (std::size_t k = 1; k + 1 < r.curve.size(); ++k) {
      const Vec2 p = r.curve[k].position;
      const double edge =
          world.land().distanceToBoundary(geometry::closestPointOnSegment(p, a, b), clearance);
      const double needed = std::min(clearance, edge) - 1.0; // stored positions are rounded
      ++points;
      near += world.land().distanceToBoundary(p, clearance) < needed ? 1 : 0;
    }
  }
  EXPECT_GT(points, 10000u);
  EXPECT_EQ(near, 0u);
}

TEST(World, AlmostAllLandDrainsToTheSeaOrALake) {
  const quality::DrainageReport report =
      quality::checkDrainage(quality::rasterizeWorld(defaultWorld(), 30.0, 2), 1.0);
  EXPECT_GT(report.landCells, 900000u);
  EXPECT_GE(report.drainingFraction, 0.99) << report.pits << " pits";
}

TEST(World, RasterMarksTheLandTheShorelineCrossesAsShore) {
  const World& world = defaultWorld();
  const quality::HeightRaster raster =
      quality::rasterizeWorld(world, 120.0, 2, quality::RiverBurning::kNone);
  std::size_t shore = 0;
  for (std::size_t i = 0; i < raster.cellClass.size(); ++i) {
    const int x = int(i % std::size_t(raster.width)), y = int(i / std::size_t(raster.width));
    const geometry::Vec2 p = raster.origin + geometry::Vec2{double(x), double(y)} * 120.0;
    const double toShore = world.land().distanceToBoundary(p, 1000.0);
    const auto cls = quality::CellClass(raster.cellClass[i]);
    if (cls == quality::CellClass::kShore) {
      ++shore;
      EXPECT_TRUE(world.land().contains(p));
      EXPECT_LT(toShore, 60.0);
    } else if (cls == quality::CellClass::kLand) {
      EXPECT_GE(toShore, 60.0);
    }
  }
  EXPECT_GT(shore, 100u);
}

TEST(World, FarthestLandFromTheRiversIsLandAtTheGreatestDistance) {
  const World& world = defaultWorld();
  constexpr double kCell = 120.0;
  const quality::HeightRaster raster =
      quality::rasterizeWorld(world, kCell, 2, quality::RiverBurning::kNone);
  const quality::NetworkReliefFigures figures =
      quality::compareWithRivers(world, raster, quality::computeFlowField(raster));
  const geometry::Vec2 far = figures.farthestFromRivers;
  EXPECT_TRUE(world.land().contains(far)) << far.x << ", " << far.y;
  double nearest = std::numeric_limits<double>::infinity();
  for (const std::vector<geometry::Vec2>& line : quality::riverCentrelines(world))
    for (std::size_t k = 0; k + 1 < line.size(); ++k)
      nearest = std::min(nearest, geometry::pointSegmentDistance(far, line[k], line[k + 1]));
  // Distances run between cell centres: within a cell diagonal of the exact one.
  EXPECT_NEAR(nearest, figures.riverDistanceMaxM, kCell * std::sqrt(2.0));
}

TEST(World, CoastSitsAtSeaLevelAndTheSeaHasDepth) {
  const World& world = defaultWorld();
  const geometry::Ring& coast = world.data().land[0].outer;
  std::size_t checked = 0;
  for (std::size_t i = 0; i < coast.size(); i += 5) {
    const World::Evaluation e = world.evaluate(coast[i], 10.0);
    if (e.rivers.w > 0.0)
      continue; // river mouths cut below sea level
    EXPECT_NEAR(e.height, 0.0, 0.5);
    ++checked;
  }
  EXPECT_GT(checked, 50u);
  const Vec2 farOut = world.land().bounds().max + Vec2{20000.0, 20000.0};
  const World::Evaluation sea = world.evaluate(farOut, 100.0);
  EXPECT_EQ(sea.terrain.w, 0.0);
  EXPECT_EQ(sea.rivers.w, 0.0);
  EXPECT_LT(sea.height, -0.9 * CoastShape::kShelfDepth);
}

TEST(World, ShelfFollowsItsExponentialProfile) {
  // The shelf's e^x is computed in plain arithmetic (the same bits on every instruction set);
  // it must agree with the library's to far below a millimetre.
  const World& world = defaultWorld();
  const geometry::Aabb box = world.land().bounds();
  base::Rng rng(5);
  int checked = 0;
  for (int i = 0; i < 2000 && checked < 300; ++i) {
    const Vec2 p{rng.uniform(box.min.x - 15000.0, box.max.x + 15000.0),
                 rng.uniform(box.min.y - 15000.0, box.max.y + 15000.0)};
    const World::Evaluation e = world.evaluate(p, 10.0);
    if (world.land().contains(p) || e.rivers.w > 0.0)
      continue;
    const double d = world.land().distanceToBoundary(p, World::shelfReach());
    const double expected =
        -CoastShape::kShelfDepth * (1.0 - std::exp(-d / CoastShape::kShelfWidth));
    ASSERT_NEAR(e.height, expected, 1e-9) << "at " << p.x << ", " << p.y;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(World, TerrainCoversTheLand) {
  const World& world = defaultWorld();
  const geometry::Aabb box = world.land().bounds();
  std::size_t land = 0;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 100; ++j) {
      const Vec2 p = box.min + Vec2{box.size().x * (i + 0.5) / 200, box.size().y * (j + 0.5) / 100};
      if (!world.land().contains(p))
        continue;
      ++land;
      const World::Evaluation e = world.evaluate(p, 50.0);
      ASSERT_GT(e.terrain.w, 0.0) << p.x << ", " << p.y;
      ASSERT_TRUE(std::isfinite(e.height));
      ASSERT_GT(e.height, -20.0);
      ASSERT_LT(e.height, 3000.0);
    }
  EXPECT_GT(land, 5000u);
}

TEST(World, CoarserSpacingOnlyFadesShortOctavesAndWidensFloors) {
  const World& world = defaultWorld();
  const geometry::Aabb box = world.land().bounds();
  double worst = 0.0;
  for (int i = 0; i < 400; ++i) {
    const Vec2 p = box.min + Vec2{box.size().x * (i + 0.5) / 400, box.size().y * 0.5};
    const World::Evaluation fine = world.evaluate(p, 1.0);
    const World::Evaluation coarse = world.evaluate(p, 60.0);
    // Same primitives: only the noise and the rivers' floors (primitives::riverFloor) differ
    // (every river's radius spans four 60 m samples: none fades)...
    ASSERT_EQ(fine.terrain.w, coarse.terrain.w);
    worst = std::max(worst, std::abs(fine.height - coarse.height));
  }
  // ... by at most the amplitude of the octaves under 2 km (a few tens of metres).
  EXPECT_LT(worst, 60.0);
  EXPECT_GT(worst, 0.0);
}

TEST(World, RiversNarrowerThanTheSamplesFade) {
  const World& world = defaultWorld();
  int onFloor = 0, faded = 0, rivers = 0;
  for (const primitives::RiverPrimitive& r : world.data().rivers) {
    const Vec2 middle = r.curve[r.curve.size() / 2].position;
    ++rivers;
    // Whole at fine spacing: its floor has weight 1.
    onFloor += world.evaluate(middle, 1.0).rivers.w == 1.0;
    // Gone where its radius spans one sample (primitives::riverFade): other rivers may still
    // reach the point, but not with the weight of a floor.
    faded += world.evaluate(middle, r.radius).rivers.w < 1.0;
  }
  EXPECT_EQ(onFloor, rivers);
  EXPECT_GT(faded, rivers * 9 / 10) << faded << " of " << rivers;
}

TEST(World, GenerationIsDeterministic) {
  STRAHLER_ASSIGN_OR_ASSERT(const auto a,
                            generateWorldData(test_support::defaultIslandSpec(3), "k"));
  STRAHLER_ASSIGN_OR_ASSERT(const auto b,
                            generateWorldData(test_support::defaultIslandSpec(3), "k"));
  EXPECT_EQ(a.terrain, b.terrain);
  EXPECT_EQ(a.rivers, b.rivers);
  EXPECT_EQ(a.blocks, b.blocks);
  EXPECT_EQ(a.flow, b.flow);
  const World wa(a), wb(b);
  for (int i = 0; i < 100; ++i) {
    const Vec2 p{i * 173.0 - 8000.0, i * 59.0 - 3000.0};
    EXPECT_EQ(wa.height(p, 2.0), wb.height(p, 2.0));
  }
}

TEST(World, HasAboutTenTerrainPrimitivesPerKm2) {
  const World& world = defaultWorld();
  const double perKm2 = double(world.data().terrain.size()) / world.data().areaKm2();
  EXPECT_GT(perKm2, 7.0);
  EXPECT_LT(perKm2, 13.0);
  EXPECT_EQ(world.data().rivers.size(), world.data().network.edgeCount());
  EXPECT_EQ(world.data().blocks.size(), world.data().network.nodes.size());
}

} // namespace
} // namespace strahler::construction
