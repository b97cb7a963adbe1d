#include "corsica_drawn_features.h"
#include "result_matchers.h"
#include "test_worlds.h"

#include "strahler/analysis/hydrology.h"
#include "strahler/construction/world.h"
#include "strahler/construction/world_builder.h"
#include "strahler/geometry/distance.h"
#include "strahler/network/drawn_rivers.h"
#include "strahler/quality/drainage.h"
#include "strahler/quality/river_profile.h"
#include "strahler/quality/world_raster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

namespace strahler::construction {
namespace {

using geometry::Vec2;

/// Sample spacing of zoom 14 at Corsica's latitude (~9.55 m · cos 42°), rounded up to 10 m.
constexpr double kZoom14Spacing = 10.0;

input::WorldSpec drawnCorsicaSpec() {
  input::WorldSpec spec = test_support::corsicaSpec();
  spec.features = test_support::corsicaDrawnFeatures(spec);
  return spec;
}

/// Corsica with the drawn features of issue 27, generated once for the suite.
const World& drawnCorsicaWorld() {
  static const std::unique_ptr<World> world = [] {
    const auto start = std::chrono::steady_clock::now();
    auto data = generateWorldData(drawnCorsicaSpec(), "drawn");
    std::printf("Corsica with drawn features generated in %.2f s\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    EXPECT_TRUE(data.ok()) << data.error().message;
    return std::make_unique<World>(test_support::valueOf(std::move(data)));
  }();
  return *world;
}

/// The drawn rivers' courses as the network holds them (mouths snapped to the shore).
std::vector<network::DrawnCourse> courses(const World& world) {
  std::vector<network::DrawnCourse> out;
  for (const input::RiverFeature& r : world.data().features.rivers)
    out.push_back(*network::drawnCourse(r, world.land(), world.data().params));
  return out;
}

TEST(DrawnRiversWorld, RiverCurvesPassThroughEveryDrawnVertex) {
  const World& world = drawnCorsicaWorld();
  ASSERT_EQ(world.data().features.rivers.size(), 2u);
  double worst = 0.0;
  for (const network::DrawnCourse& course : courses(world))
    for (Vec2 v : course.line) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const primitives::RiverPrimitive& r : world.data().rivers)
        for (std::size_t k = 1; k < r.curve.size(); ++k)
          nearest = std::min(nearest, geometry::pointSegmentDistance(v, r.curve[k - 1].position,
                                                                     r.curve[k].position));
      worst = std::max(worst, nearest);
    }
  std::printf("largest distance from a drawn vertex to a river curve: %.3f m\n", worst);
  EXPECT_LT(worst, 1.0);
}

// At zoom 14's sample spacing, the lowest height across a drawn river (±100 m) lies on the
// drawn line (within one sample spacing), and the line is lower than the ground 100 m to
// either side: the channel is carved where it was drawn.
TEST(DrawnRiversWorld, TheCarvedChannelFollowsTheDrawnLine) {
  const World& world = drawnCorsicaWorld();
  constexpr double kAcross = 100.0, kStep = 2.0;
  std::size_t samples = 0, notLower = 0;
  double worst = 0.0;
  Vec2 worstAt;
  // Where a grown tributary joins a drawn river, the lowest sample across may lie in the
  // tributary's channel: the junctions (a node on a drawn line whose child is not).
  const std::vector<network::DrawnCourse> drawnCourses = courses(world);
  auto onCourse = [&](Vec2 q) {
    for (const network::DrawnCourse& course : drawnCourses)
      for (std::size_t k = 1; k < course.line.size(); ++k)
        if (geometry::pointSegmentDistance(q, course.line[k - 1], course.line[k]) < 1.0)
          return true;
    return false;
  };
  std::vector<Vec2> junctions;
  const network::RiverNetwork& network = world.data().network;
  for (const network::RiverNode& n : network.nodes)
    if (n.parent.valid() && onCourse(network.node(n.parent).position) && !onCourse(n.position))
      junctions.push_back(network.node(n.parent).position);
  for (const network::DrawnCourse& course : drawnCourses) {
    for (double s = 0.0; s < course.arc.back(); s += kZoom14Spacing) {
      const Vec2 p = course.at(s);
      if (std::any_of(junctions.begin(), junctions.end(),
                      [&](Vec2 j) { return distance(j, p) < kAcross; }))
        continue;
      // Near the mouth the sea lies to the sides; near a vertex where the line turns, the
      // samples across on the inside of the bend fall on the line's other leg.
      if (world.land().distanceToBoundary(p, 2.0 * kAcross) < 2.0 * kAcross)
        continue;
      const bool nearVertex =
          std::any_of(course.arc.begin() + 1, course.arc.end() - 1,
                      [&](double v) { return std::abs(v - s) < 2.0 * kAcross; });
      if (nearVertex)
        continue;
      const Vec2 tangent = normalize(course.at(s + 1.0) - course.at(std::max(0.0, s - 1.0)));
      const Vec2 normal = perpendicular(tangent);
      const double here = world.height(p, kZoom14Spacing);
      // The lowest sample across, the nearest to the line among equals.
      double lowest = here, at = 0.0;
      for (double d = kStep; d <= kAcross; d += kStep)
        for (double side : {-1.0, 1.0}) {
          const double h = world.height(p + normal * (side * d), kZoom14Spacing);
          if (h < lowest) {
            lowest = h;
            at = d;
          }
        }
      ++samples;
      if (at > worst) {
        worst = at;
        worstAt = p;
      }
      const double left = world.height(p - normal * kAcross, kZoom14Spacing);
      const double right = world.height(p + normal * kAcross, kZoom14Spacing);
      notLower += here < left && here < right ? 0 : 1;
    }
  }
  std::printf("largest distance from a drawn line to the lowest sample across it: %.1f m "
              "(at %.0f, %.0f); %zu of %zu samples not below both sides\n",
              worst, worstAt.x, worstAt.y, notLower, samples);
  EXPECT_GT(samples, 5000u);
  EXPECT_LE(worst, kZoom14Spacing);
  EXPECT_EQ(notLower, 0u);
}

// Every river's centreline, sampled every 5 m at 1 m spacing, never rises by more than 0.5 m
// (a channel that met a neighbouring one, a sibling meandering across its course, took the
// other's lower bed there and read as a rise: river_primitives.cpp keeps channels apart).
TEST(DrawnRiversWorld, RiversNeverRiseDownstream) {
  const World& world = drawnCorsicaWorld();
  const quality::RiverProfileReport report = quality::checkRiversDescend(
      quality::riverCentrelines(world), [&](Vec2 p) { return world.height(p, 1.0); }, 5.0, 0.5);
  std::printf("river profiles: %zu samples, %zu violations\n", report.samples, report.violations);
  EXPECT_GT(report.samples, 10000u);
  EXPECT_EQ(report.violations, 0u) << "worst rise " << report.worstRise << " m at "
                                   << report.worstAt.x << ", " << report.worstAt.y;
}

TEST(DrawnRiversWorld, AlmostAllLandDrainsWithoutBurning) {
  const quality::DrainageReport report = quality::checkDrainage(
      quality::rasterizeWorld(drawnCorsicaWorld(), 60.0, 2, quality::RiverBurning::kNone), 1.0);
  std::printf("drainage without burning (60 m cells): %.4f of %zu land cells, %zu pits\n",
              report.drainingFraction, report.landCells, report.pits);
  EXPECT_GT(report.landCells, 2000000u);
  EXPECT_GE(report.drainingFraction, 0.995) << report.pits << " pits";
}

// A drawn river is the trunk of its tree: its mouth drains the whole tree, so its drainage
// area is at least the sum of its tributaries' (the chain's own blocks add to it), and its
// flow at least any tributary's (flow grows as A^0.69, so it is less than their sum).
TEST(DrawnRiversWorld, ADrawnRiverCarriesTheFlowOfItsTributaries) {
  const input::WorldSpec spec = drawnCorsicaSpec();
  const analysis::Hydrology h = test_support::valueOf(analysis::buildHydrology(spec));
  for (std::size_t r = 0; r < spec.features.rivers.size(); ++r) {
    const network::DrawnCourse course =
        *network::drawnCourse(spec.features.rivers[r], *h.land, spec.params);
    network::NodeId node = h.network.mouths[r].node;
    const std::size_t mouth = node.index();
    double tributaryArea = 0.0, largestTributaryFlow = 0.0;
    std::size_t tributaries = 0;
    for (std::size_t k = 1; k <= course.chain.size(); ++k) {
      network::NodeId next;
      for (network::NodeId c : h.network.node(node).children) {
        if (k < course.chain.size() && h.network.node(c).position == course.node(k)) {
          next = c;
          continue;
        }
        ++tributaries;
        tributaryArea += h.analysis.drainageAreaKm2[c.index()];
        largestTributaryFlow = std::max(largestTributaryFlow, h.analysis.flow[c.index()]);
      }
      if (k == course.chain.size())
        break;
      ASSERT_TRUE(next.valid()) << "chain node " << k;
      node = next;
    }
    std::printf("%s: %zu tributaries, %.0f km² at the mouth (%.0f km² in tributaries), "
                "flow %.1f m³/s\n",
                spec.features.rivers[r].name.c_str(), tributaries,
                h.analysis.drainageAreaKm2[mouth], tributaryArea, h.analysis.flow[mouth]);
    EXPECT_GT(tributaries, 10u);
    EXPECT_GE(h.analysis.drainageAreaKm2[mouth], tributaryArea);
    EXPECT_GE(h.analysis.flow[mouth], largestTributaryFlow);
    EXPECT_DOUBLE_EQ(h.analysis.flow[mouth],
                     analysis::flowFromArea(h.analysis.drainageAreaKm2[mouth]));
  }
}

} // namespace
} // namespace strahler::construction
