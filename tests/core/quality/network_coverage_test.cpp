#include "strahler/quality/network_coverage.h"

#include <gtest/gtest.h>

#include <cmath>

namespace strahler::quality {
namespace {

using geometry::Vec2;

/// A square island of side 10 km, its corner at the origin.
geometry::PolygonIndex squareIsland() {
  geometry::Polygon square;
  square.outer = {{0.0, 0.0}, {10000.0, 0.0}, {10000.0, 10000.0}, {0.0, 10000.0}};
  return geometry::PolygonIndex(geometry::MultiPolygon{square});
}

/// A river along y = `y` from x = 0 (its mouth) to x = `length`, in edges of 1 km.
network::RiverNetwork straightRiver(double y, double length) {
  network::RiverNetwork net;
  net.edgeLength = 1000.0;
  for (double x = 0.0; x <= length + 1e-9; x += 1000.0) {
    network::RiverNode node;
    node.position = {x, y};
    const auto id = network::NodeId(static_cast<std::uint32_t>(net.nodes.size()));
    if (!net.nodes.empty()) {
      node.parent = network::NodeId(id.value - 1);
      net.nodes.back().children.push_back(id);
    }
    net.nodes.push_back(node);
  }
  net.mouths.push_back({network::NodeId(0), {1.0, 0.0}, false});
  return net;
}

TEST(NetworkCoverage, ARiverAcrossTheMiddleLeavesTheShoresFiveKilometresAway) {
  const geometry::PolygonIndex land = squareIsland();
  const NetworkCoverage c = networkCoverage(straightRiver(5000.0, 10000.0), land, 100.0);
  // The farthest cell centres lie 50 m inside the north or south shore, 4950 m from the
  // river's cells (whose centres are 50 m off the line): 4900 to 5000 m.
  EXPECT_NEAR(c.farthestM, 4950.0, 100.0);
  EXPECT_NEAR(std::abs(c.farthestAt.y - 5000.0), 4950.0, 100.0);
  EXPECT_DOUBLE_EQ(c.cellSize, 100.0);
  // Land farther than 3 km: the two bands within 2 km of the north and south shores.
  EXPECT_NEAR(c.fartherThan3KmFraction, 0.4, 0.02);
}

TEST(NetworkCoverage, AShortRiverLeavesTheFarCornersFarthest) {
  const geometry::PolygonIndex land = squareIsland();
  // From (0, 5 km) to (2 km, 5 km): the east corners are √(8² + 5²) km from its head.
  const NetworkCoverage c = networkCoverage(straightRiver(5000.0, 2000.0), land, 100.0);
  EXPECT_NEAR(c.farthestM, std::hypot(8000.0, 5000.0), 150.0);
  EXPECT_GT(c.farthestAt.x, 9800.0);
}

TEST(NetworkCoverage, IsUndefinedWithoutEdges) {
  const geometry::PolygonIndex land = squareIsland();
  network::RiverNetwork mouthOnly = straightRiver(5000.0, 0.0);
  const NetworkCoverage c = networkCoverage(mouthOnly, land, 100.0);
  EXPECT_TRUE(std::isnan(c.farthestM));
  EXPECT_TRUE(std::isnan(c.fartherThan3KmFraction));
}

} // namespace
} // namespace strahler::quality
