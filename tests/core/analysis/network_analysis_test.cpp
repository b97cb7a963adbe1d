#include "result_matchers.h"
#include "test_worlds.h"

#include "strahler/analysis/hydrology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace strahler::analysis {
namespace {

class HydrologyOf : public ::testing::TestWithParam<std::string> {
protected:
  void SetUp() override {
    spec_ =
        GetParam() == "mallorca" ? test_support::mallorcaSpec() : test_support::defaultIslandSpec();
    auto h = buildHydrology(spec_);
    ASSERT_TRUE(h.ok()) << h.error().message;
    h_ = std::move(h).value();
  }
  input::WorldSpec spec_;
  Hydrology h_;
};

TEST_P(HydrologyOf, BlocksPartitionTheLand) {
  ASSERT_EQ(h_.blocks.blocks.size(), h_.network.nodes.size());
  double sum = 0.0;
  for (const blocks::Block& b : h_.blocks.blocks)
    sum += b.area;
  const double land = geometry::area(spec_.land);
  EXPECT_NEAR(sum / land, 1.0, 1e-3);
}

TEST_P(HydrologyOf, FlowAtEachNodeFollowsItsUpstreamBlocks) {
  const auto& nodes = h_.network.nodes;
  std::vector<double> upstreamKm2(nodes.size(), 0.0);
  // Brute force: every block adds its area to its own node and every node downstream.
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const double a = h_.blocks.blocks[i].area / 1e6;
    for (std::size_t cur = i;; cur = nodes[cur].parent.index()) {
      upstreamKm2[cur] += a;
      if (!nodes[cur].parent.valid())
        break;
    }
  }
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    ASSERT_NEAR(h_.analysis.drainageAreaKm2[i], upstreamKm2[i], 1e-9 * (1 + upstreamKm2[i]));
    ASSERT_NEAR(h_.analysis.flow[i], 0.42 * std::pow(upstreamKm2[i], 0.69),
                1e-9 * (1 + h_.analysis.flow[i]));
  }
  double basins = 0.0;
  for (double a : h_.analysis.watershedAreaKm2)
    basins += a;
  EXPECT_NEAR(basins, spec_.areaKm2(), 1e-3 * spec_.areaKm2());
}

TEST_P(HydrologyOf, RidgeVerticesAreHigherThanTheirCellsRiverNodes) {
  ASSERT_EQ(h_.analysis.ridgeElevation.size(), h_.blocks.vertices.size());
  for (std::size_t v = 0; v < h_.blocks.vertices.size(); ++v)
    for (network::NodeId site : h_.blocks.vertices[v].sites)
      ASSERT_GT(h_.analysis.ridgeElevation[v], h_.network.node(site).elevation);
}

TEST_P(HydrologyOf, RosgenTypesFollowTheirRules) {
  const input::Params& p = spec_.params;
  std::size_t counts[4] = {};
  for (std::size_t i = 0; i < h_.network.nodes.size(); ++i) {
    const network::RiverNode& n = h_.network.nodes[i];
    const RosgenType t = h_.analysis.rosgen[i];
    ++counts[static_cast<int>(t)];
    if (t == RosgenType::kDelta) {
      EXPECT_FALSE(n.parent.valid());
      EXPECT_GE(h_.analysis.flow[i], p.deltaMinFlow);
    } else if (t == RosgenType::kBraided) {
      EXPECT_GE(h_.analysis.flow[i], p.braidedMinFlow);
      EXPECT_LE(h_.analysis.distanceToMouth[i], p.braidedMaxDistance);
    } else if (n.parent.valid()) {
      const double slope = (n.elevation - h_.network.node(n.parent).elevation) / p.edgeLength;
      EXPECT_EQ(t == RosgenType::kStraight, slope >= p.straightMinSlope);
    }
  }
  // A real island has all four kinds of river.
  for (std::size_t c : counts)
    EXPECT_GT(c, 0u);
}

INSTANTIATE_TEST_SUITE_P(Worlds, HydrologyOf, ::testing::Values("default", "mallorca"));

TEST(Hydrology, IsDeterministic) {
  const input::WorldSpec spec = test_support::defaultIslandSpec(11);
  STRAHLER_ASSIGN_OR_ASSERT(const Hydrology a, buildHydrology(spec));
  STRAHLER_ASSIGN_OR_ASSERT(const Hydrology b, buildHydrology(spec));
  ASSERT_EQ(a.blocks.vertices.size(), b.blocks.vertices.size());
  for (std::size_t v = 0; v < a.blocks.vertices.size(); ++v) {
    ASSERT_EQ(std::memcmp(&a.blocks.vertices[v].position, &b.blocks.vertices[v].position,
                          sizeof(geometry::Vec2)),
              0);
    ASSERT_EQ(a.analysis.ridgeElevation[v], b.analysis.ridgeElevation[v]);
  }
  ASSERT_EQ(a.analysis.flow, b.analysis.flow);
}

TEST(Hydrology, RiverSlopesFollowTheSlopeAreaLaw) {
  // With one river slope s everywhere, every edge falls by s · (A / referenceArea)^−θ per
  // metre, A its upstream node's drainage area: steep headwaters, gentle trunks.
  input::WorldSpec spec = test_support::defaultIslandSpec();
  spec.params.slopeMin = spec.params.slopeMax = 0.05;
  STRAHLER_ASSIGN_OR_ASSERT(const Hydrology h, buildHydrology(spec));
  double steepest = 0.0, gentlest = 1.0;
  for (std::size_t i = 0; i < h.network.nodes.size(); ++i) {
    const network::RiverNode& node = h.network.nodes[i];
    if (!node.parent.valid())
      continue;
    const network::RiverNode& parent = h.network.node(node.parent);
    const double length = distance(node.position, parent.position);
    const double expected =
        0.05 *
        std::pow(h.analysis.drainageAreaKm2[i] / spec.params.referenceArea, -spec.params.concavity);
    const double slope = (node.elevation - parent.elevation) / length;
    ASSERT_NEAR(slope, std::max(expected, 0.01 / length), 1e-9 * expected) << "node " << i;
    steepest = std::max(steepest, slope);
    gentlest = std::min(gentlest, slope);
  }
  // θ = 0.3: (A / 10 km²)^−0.3 is 1.6 at 2 km², 0.6 at 50 km².
  EXPECT_GT(steepest, 0.05 * 1.5) << "headwaters (A < 2 km²) are over 1.5 times as steep";
  EXPECT_LT(gentlest, 0.05 * 0.6) << "the largest rivers (A > 50 km²) under 0.6 times as steep";
}

TEST(FlowFromArea, FollowsDunneAndLeopold) {
  EXPECT_DOUBLE_EQ(flowFromArea(1.0), 0.42);
  EXPECT_NEAR(flowFromArea(100.0), 0.42 * std::pow(100.0, 0.69), 1e-12);
  EXPECT_EQ(flowFromArea(0.0), 0.0);
}

} // namespace
} // namespace strahler::analysis
