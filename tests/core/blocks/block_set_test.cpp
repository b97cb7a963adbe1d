#include "blocks_test_support.h"

#include "strahler/blocks/block_set.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace strahler::blocks {
namespace {

using geometry::PolygonIndex;
using geometry::Vec2;
using test_support::build;
using test_support::expectConsistentBlocks;
using test_support::networkAt;
using test_support::rectangle;
using test_support::totalArea;

PolygonIndex squareLand(double side) {
  return PolygonIndex({geometry::Polygon{rectangle({0, 0}, {side, side}), {}}});
}

std::vector<Vec2> gridSites(int n, double spacing) {
  std::vector<Vec2> sites;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      sites.push_back({spacing * (i + 0.5), spacing * (j + 0.5)});
  return sites;
}

TEST(BlockSet, GridOfNodesSplitsASquareIntoEqualBlocks) {
  const PolygonIndex land = squareLand(400.0);
  const std::vector<Vec2> sites = gridSites(4, 100.0);
  const BlockSet set = build(sites, land);
  ASSERT_EQ(set.blocks.size(), 16u);
  for (const Block& b : set.blocks)
    EXPECT_NEAR(b.area, 160000.0 / 16, 1e-6 * 10000.0);
  expectConsistentBlocks(set, sites);
}

TEST(BlockSet, VoronoiVerticesAreEquidistantFromTheirSites) {
  const PolygonIndex land = squareLand(400.0);
  const std::vector<Vec2> sites = gridSites(4, 100.0);
  const BlockSet set = build(sites, land);
  ASSERT_FALSE(set.vertices.empty());
  for (const VoronoiVertex& v : set.vertices)
    for (NodeId s : v.sites)
      EXPECT_NEAR(geometry::distance(v.position, sites[s.index()]), v.radius, 1e-9 * v.radius);
}

TEST(BlockSet, GridNeighboursAreTheFourAdjacentNodes) {
  // Grid squares are cocircular: the diagonal Voronoi edges have zero length and are dropped.
  const std::vector<Vec2> sites = gridSites(4, 100.0);
  const BlockSet set = build(sites, squareLand(400.0));
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      std::set<std::uint32_t> expected;
      if (i > 0)
        expected.insert(static_cast<std::uint32_t>(j * 4 + i - 1));
      if (i < 3)
        expected.insert(static_cast<std::uint32_t>(j * 4 + i + 1));
      if (j > 0)
        expected.insert(static_cast<std::uint32_t>((j - 1) * 4 + i));
      if (j < 3)
        expected.insert(static_cast<std::uint32_t>((j + 1) * 4 + i));
      std::set<std::uint32_t> actual;
      for (NodeId w : set.blocks[static_cast<std::size_t>(j * 4 + i)].neighbours)
        if (w.valid())
          actual.insert(w.value);
      EXPECT_EQ(actual, expected) << "node " << j * 4 + i;
    }
  }
}

TEST(BlockSet, FrameHoldsLandAndNodesWithAMargin) {
  const PolygonIndex land = squareLand(400.0);
  const BlockSet set = build({{100, 100}, {300, 200}, {-500, 50}}, land);
  EXPECT_LT(set.frame.min.x, -500.0 - 1000.0);
  EXPECT_GT(set.frame.max.x, 400.0 + 1000.0);
  EXPECT_LT(set.frame.min.y, -1000.0);
  EXPECT_GT(set.frame.max.y, 400.0 + 1000.0);
}

TEST(BlockSet, DuplicateNodesAreAnErrorNamingBoth) {
  std::vector<Vec2> sites = gridSites(4, 100.0);
  sites[12] = sites[5];
  const auto result = buildBlocks(networkAt(sites), squareLand(400.0));
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, base::ErrorCode::kInvalidInput);
  EXPECT_NE(result.error().message.find("5 and 12"), std::string::npos) << result.error().message;
}

TEST(BlockSet, NonFinitePositionIsAnError) {
  std::vector<Vec2> sites = gridSites(2, 100.0);
  sites[3].y = std::numeric_limits<double>::quiet_NaN();
  const auto result = buildBlocks(networkAt(sites), squareLand(400.0));
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, base::ErrorCode::kInvalidInput);
}

TEST(BlockSet, NoNodesGiveNoBlocks) {
  const BlockSet set = build({}, squareLand(400.0));
  EXPECT_TRUE(set.blocks.empty());
  EXPECT_TRUE(set.vertices.empty());
}

TEST(BlockSet, OneNodeOwnsTheWholeLand) {
  const std::vector<Vec2> sites{{123, 321}};
  const BlockSet set = build(sites, squareLand(400.0));
  ASSERT_EQ(set.blocks.size(), 1u);
  EXPECT_TRUE(set.vertices.empty());
  EXPECT_EQ(set.blocks[0].cell.size(), 4u);
  const double frameArea = set.frame.size().x * set.frame.size().y;
  EXPECT_NEAR(geometry::signedArea(set.blocks[0].cell), frameArea, 1e-12 * frameArea);
  EXPECT_NEAR(set.blocks[0].area, 160000.0, 1e-6);
  expectConsistentBlocks(set, sites);
}

TEST(BlockSet, TwoNodesSplitAlongTheirBisector) {
  const std::vector<Vec2> sites{{100, 100}, {300, 100}};
  const BlockSet set = build(sites, squareLand(400.0));
  ASSERT_EQ(set.blocks.size(), 2u);
  EXPECT_NEAR(set.blocks[0].area, 80000.0, 1e-6);
  EXPECT_NEAR(set.blocks[1].area, 80000.0, 1e-6);
  expectConsistentBlocks(set, sites);
  EXPECT_EQ(std::count(set.blocks[0].neighbours.begin(), set.blocks[0].neighbours.end(), NodeId(1)),
            1);
}

TEST(BlockSet, CollinearNodesGiveStrips) {
  const std::vector<Vec2> sites{{50, 50}, {350, 350}, {150, 150}, {250, 250}, {200, 200}};
  const BlockSet set = build(sites, squareLand(400.0));
  ASSERT_EQ(set.blocks.size(), 5u);
  EXPECT_TRUE(set.vertices.empty());
  EXPECT_NEAR(totalArea(set), 160000.0, 1e-6);
  expectConsistentBlocks(set, sites);
  // Along the line: 0 - 2 - 4 - 3 - 1.
  auto valid = [&](std::size_t i) {
    const auto& n = set.blocks[i].neighbours;
    return std::count_if(n.begin(), n.end(), [](NodeId w) { return w.valid(); });
  };
  EXPECT_EQ(valid(0), 1);
  EXPECT_EQ(valid(1), 1);
  EXPECT_EQ(valid(4), 2);
}

TEST(BlockSet, ThreeNodesShareOneVoronoiVertex) {
  const std::vector<Vec2> sites{{100, 100}, {300, 120}, {180, 330}};
  const BlockSet set = build(sites, squareLand(400.0));
  ASSERT_EQ(set.vertices.size(), 1u);
  for (const Block& b : set.blocks)
    EXPECT_EQ(std::count(b.cellVertices.begin(), b.cellVertices.end(), 0u), 1);
  EXPECT_NEAR(totalArea(set), 160000.0, 1e-6);
  expectConsistentBlocks(set, sites);
}

TEST(BlockSet, NodesOutsideTheLandGetEmptyRegions) {
  const std::vector<Vec2> sites{{100, 100}, {300, 300}, {900, 900}, {-300, 200}};
  const BlockSet set = build(sites, squareLand(400.0));
  EXPECT_TRUE(set.blocks[2].region.empty());
  EXPECT_EQ(set.blocks[2].area, 0.0);
  EXPECT_NEAR(totalArea(set), 160000.0, 1e-6);
  expectConsistentBlocks(set, sites);
}

} // namespace
} // namespace strahler::blocks
