#include "blocks_test_support.h"

#include "strahler/base/random.h"
#include "strahler/blocks/block_set.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace strahler::blocks {
namespace {

using geometry::MultiPolygon;
using geometry::Polygon;
using geometry::PolygonIndex;
using geometry::Ring;
using geometry::Vec2;
using test_support::build;
using test_support::expectConsistentBlocks;
using test_support::expectNearestNodeOwnsPoints;
using test_support::naiveClippedArea;
using test_support::randomPointsIn;
using test_support::rectangle;
using test_support::totalArea;

constexpr double kPi = std::numbers::pi;

/// An L-shaped island (concave) with a square lake: 64 km² minus 4 km².
MultiPolygon lakeIsland() {
  Ring outer{{0, 0}, {10000, 0}, {10000, 4000}, {4000, 4000}, {4000, 10000}, {0, 10000}};
  Ring lake = rectangle({1000, 1000}, {3000, 3000});
  std::reverse(lake.begin(), lake.end());
  return {Polygon{outer, {lake}}};
}

/// Two square islands 10 km apart.
MultiPolygon twoIslands() {
  return {Polygon{rectangle({0, 0}, {10000, 10000}), {}},
          Polygon{rectangle({20000, 0}, {30000, 5000}), {}}};
}

/// A star-shaped island of radius about 30 km with `n` vertices and a wiggly coast.
MultiPolygon starIsland(std::size_t n) {
  Ring ring;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2.0 * kPi * static_cast<double>(i) / static_cast<double>(n);
    const double r = 30000.0 * (1.0 + 0.25 * std::sin(5.0 * t) + 0.08 * std::sin(23.0 * t + 1.0) +
                                0.03 * std::sin(97.0 * t + 2.0));
    ring.push_back(geometry::direction(t) * r);
  }
  return {Polygon{ring, {}}};
}

/// A band that winds twice around its centre: long stretches of coast curl around the cells
/// and leave them on either side.
MultiPolygon spiralIsland() {
  const double a = 2000.0, b = 3000.0 / (2.0 * kPi), width = 1500.0;
  const int steps = 800;
  Ring inner, outer;
  for (int i = 0; i <= steps; ++i) {
    const double t = 4.0 * kPi * i / steps;
    inner.push_back(geometry::direction(t) * (a + b * t));
    outer.push_back(geometry::direction(t) * (a + b * t + width));
  }
  Ring ring(outer.begin(), outer.end());
  ring.insert(ring.end(), inner.rbegin(), inner.rend());
  Polygon polygon{ring, {}};
  geometry::orient(polygon);
  return {polygon};
}

/// Builds blocks for `count` random nodes in `land` and checks that they partition it.
void expectPartition(const MultiPolygon& polygons, std::size_t count, std::uint64_t seed) {
  const PolygonIndex land(polygons);
  base::Rng rng(seed);
  const std::vector<Vec2> sites = randomPointsIn(land, count, rng);
  const BlockSet set = build(sites, land);
  const double landArea = geometry::area(polygons);
  EXPECT_NEAR(totalArea(set), landArea, 1e-3 * landArea);
  EXPECT_NEAR(totalArea(set), landArea, 1e-9 * landArea); // in practice exact to rounding
  expectConsistentBlocks(set, sites);
  for (std::size_t i = 0; i < set.blocks.size(); ++i) {
    const Block& b = set.blocks[i];
    EXPECT_NEAR(b.area, naiveClippedArea(b.cell, polygons), 1e-9 * landArea) << "block " << i;
  }
  expectNearestNodeOwnsPoints(set, sites, land, 3000, rng);
}

TEST(BlockPartition, ConcaveIslandWithALake) {
  expectPartition(lakeIsland(), 300, 1);
}

TEST(BlockPartition, TwoIslands) {
  expectPartition(twoIslands(), 300, 2);
}

TEST(BlockPartition, WindingCoast) {
  expectPartition(spiralIsland(), 40, 3);
}

TEST(BlockPartition, LongCoastAndManyNodes) {
  expectPartition(starIsland(5000), 2000, 4);
}

/// Checks that `sites` partition `polygons` into consistent blocks that own their points.
void expectPartitionBy(const std::vector<Vec2>& sites, const MultiPolygon& polygons) {
  const PolygonIndex land(polygons);
  const BlockSet set = build(sites, land);
  const double landArea = geometry::area(polygons);
  EXPECT_NEAR(totalArea(set), landArea, 1e-9 * landArea);
  expectConsistentBlocks(set, sites);
  base::Rng rng(6);
  expectNearestNodeOwnsPoints(set, sites, land, 500, rng);
}

TEST(BlockPartition, RotatedGridWithRoundedHull) {
  // The grid's sides are straight only up to rounding: the triangulation gets nearly flat
  // triangles along them, whose circumcentres are huge and imprecise.
  std::vector<Vec2> sites;
  const double angle = 0.3;
  for (int j = -20; j < 20; ++j)
    for (int i = -20; i < 20; ++i)
      sites.push_back(Vec2{5, 4} + Vec2{i * std::cos(angle) - j * std::sin(angle),
                                        i * std::sin(angle) + j * std::cos(angle)} *
                                       0.37);
  expectPartitionBy(sites, {Polygon{rectangle({0.3, 0.7}, {10.3, 7.9}), {}}});
}

TEST(BlockPartition, CocircularNodes) {
  std::vector<Vec2> sites;
  for (int i = 0; i < 12; ++i)
    sites.push_back(Vec2{5.3, 4.3} + geometry::direction(2.0 * kPi * i / 12) * 3.0);
  sites.push_back({5.3, 4.3});
  expectPartitionBy(sites, {Polygon{rectangle({0.3, 0.7}, {10.3, 7.9}), {}}});
}

TEST(BlockPartition, NearlyCoincidentNodes) {
  const std::vector<Vec2> sites{{5, 4}, {5 + 1e-9, 4}, {5, 4 + 1e-9},
                                {1, 1}, {9, 7},        {5, 4 - 1e-12}};
  expectPartitionBy(sites, {Polygon{rectangle({0.3, 0.7}, {10.3, 7.9}), {}}});
}

TEST(BlockPartition, SameInputGivesIdenticalBlocks) {
  const MultiPolygon polygons = starIsland(5000);
  const PolygonIndex land(polygons);
  base::Rng rng(5);
  const std::vector<Vec2> sites = randomPointsIn(land, 2000, rng);
  const BlockSet a = build(sites, land), b = build(sites, land);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t k = 0; k < a.vertices.size(); ++k) {
    EXPECT_EQ(a.vertices[k].position, b.vertices[k].position);
    EXPECT_EQ(a.vertices[k].sites, b.vertices[k].sites);
    EXPECT_EQ(a.vertices[k].radius, b.vertices[k].radius);
  }
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    EXPECT_EQ(a.blocks[i].cell, b.blocks[i].cell);
    EXPECT_EQ(a.blocks[i].cellVertices, b.blocks[i].cellVertices);
    EXPECT_EQ(a.blocks[i].neighbours, b.blocks[i].neighbours);
    EXPECT_EQ(a.blocks[i].area, b.blocks[i].area);
    ASSERT_EQ(a.blocks[i].region.size(), b.blocks[i].region.size());
    for (std::size_t p = 0; p < a.blocks[i].region.size(); ++p) {
      EXPECT_EQ(a.blocks[i].region[p].outer, b.blocks[i].region[p].outer);
      EXPECT_EQ(a.blocks[i].region[p].holes, b.blocks[i].region[p].holes);
    }
  }
}

} // namespace
} // namespace strahler::blocks
