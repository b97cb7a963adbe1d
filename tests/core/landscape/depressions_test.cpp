#include "strahler/base/random.h"
#include "strahler/landscape/depressions.h"

#include <gtest/gtest.h>

namespace strahler::landscape {
namespace {

/// A grid of random heights whose border is base level.
void randomGrid(int size, std::uint64_t seed, LatticeGrid<double>& heights,
                LatticeGrid<NodeRole>& roles) {
  heights = LatticeGrid<double>::filled(size, size, 0.0);
  roles = LatticeGrid<NodeRole>::filled(size, size, NodeRole::kFree);
  base::Rng rng(seed);
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c) {
      heights.values[heights.at(c, r)] = rng.uniform(0.0, 100.0);
      if (r == 0 || c == 0 || r + 1 == size || c + 1 == size)
        roles.values[roles.at(c, r)] = NodeRole::kBaseLevel;
    }
}

/// Whether node (c, r) has an edge neighbour at least `drop` lower.
bool hasLowerEdgeNeighbour(const LatticeGrid<double>& h, int c, int r, double drop) {
  const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (const auto& o : offsets)
    if (h.values[h.at(c + o[0], r + o[1])] <= h.values[h.at(c, r)] - drop)
      return true;
  return false;
}

TEST(Depressions, EveryFreeNodeFallsToAFixedOneThroughEdgeNeighbours) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    LatticeGrid<double> heights;
    LatticeGrid<NodeRole> roles;
    randomGrid(40, seed, heights, roles);
    const LatticeGrid<double> before = heights;
    fillDepressions(heights, roles, 0.01);
    for (int r = 1; r + 1 < 40; ++r)
      for (int c = 1; c + 1 < 40; ++c) {
        // A strictly lower edge neighbour everywhere: following them ends at the border.
        ASSERT_TRUE(hasLowerEdgeNeighbour(heights, c, r, 0.01 - 1e-9)) << c << ", " << r;
        // Filling only raises.
        ASSERT_GE(heights.values[heights.at(c, r)], before.values[before.at(c, r)]);
      }
  }
}

TEST(Depressions, FixedNodesAndDrainingLandKeepTheirHeights) {
  // A plane tilted down to the base-level column 0 has no depression: nothing moves.
  LatticeGrid<double> heights = LatticeGrid<double>::filled(10, 10, 0.0);
  LatticeGrid<NodeRole> roles = LatticeGrid<NodeRole>::filled(10, 10, NodeRole::kFree);
  for (int r = 0; r < 10; ++r)
    for (int c = 0; c < 10; ++c) {
      heights.values[heights.at(c, r)] = 5.0 * c + 0.1 * r;
      if (c == 0)
        roles.values[roles.at(c, r)] = NodeRole::kBaseLevel;
    }
  const LatticeGrid<double> before = heights;
  fillDepressions(heights, roles, 0.01);
  EXPECT_EQ(heights.values, before.values);
}

TEST(Depressions, APitIsRaisedToItsSpillPlusTheGradient) {
  // A single pit at 1 m in a 10 m plateau whose only outlet is a base-level node at 0 m.
  LatticeGrid<double> heights = LatticeGrid<double>::filled(5, 5, 10.0);
  LatticeGrid<NodeRole> roles = LatticeGrid<NodeRole>::filled(5, 5, NodeRole::kPinned);
  for (int r = 1; r < 4; ++r)
    for (int c = 1; c < 4; ++c)
      roles.values[roles.at(c, r)] = NodeRole::kFree;
  heights.values[heights.at(2, 0)] = 0.0; // the outlet, edge neighbour of (2, 1)
  heights.values[heights.at(2, 2)] = 1.0; // the pit, behind (2, 1)
  heights.values[heights.at(2, 1)] = 5.0;
  fillDepressions(heights, roles, 0.5);
  EXPECT_DOUBLE_EQ(heights.values[heights.at(2, 1)], 5.0); // drains to the outlet already
  EXPECT_DOUBLE_EQ(heights.values[heights.at(2, 2)], 5.5); // spill 5 m + one step of 0.5 m
}

} // namespace
} // namespace strahler::landscape
