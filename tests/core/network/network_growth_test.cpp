#include "grown_world.h"
#include "test_worlds.h"

#include "strahler/geometry/distance.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/network/network_growth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <tuple>

namespace strahler::network {
namespace {

using input::NetworkGrower;

/// The rules of Section 4.2.2 that every grower keeps, on each world.
class NetworkInvariants : public ::testing::TestWithParam<std::tuple<NetworkGrower, std::string>> {
protected:
  static const GrownWorld& grown() {
    return grownWorld(std::get<0>(GetParam()), std::get<1>(GetParam()));
  }
};

TEST(NetworkGrowth, GrowsAPlausibleNetwork) {
  for (const char* name : {"default", "mallorca"}) {
    const GrownWorld& w = grownWorld(NetworkGrower::kGrammar, name);
    EXPECT_GT(w.network.mouths.size(), 3u);
    // At least one node per 2 km², as in the paper's islands (Table 2: ~1 per 2.6 km²).
    EXPECT_GT(double(w.network.nodes.size()), w.spec.areaKm2() / 2.0);
    int highest = 0;
    for (const RiverNode& n : w.network.nodes)
      highest = std::max(highest, n.strahler);
    EXPECT_GE(highest, 4);
  }
}

TEST_P(NetworkInvariants, NodesAreInsideTheLandAndAwayFromTheCoast) {
  const GrownWorld& w = grown();
  const double delta = w.spec.params.delta;
  for (const RiverNode& n : w.network.nodes) {
    if (!n.parent.valid()) {
      EXPECT_LT(w.land->distanceToBoundary(n.position, 1.0), 1e-6) << "mouths lie on the shore";
      continue;
    }
    ASSERT_TRUE(w.land->contains(n.position));
    ASSERT_GT(w.land->distanceToBoundary(n.position, delta + 1.0), delta);
  }
}

TEST_P(NetworkInvariants, NonAdjacentEdgesAreAtLeastSigmaApart) {
  const GrownWorld& w = grown();
  const auto& nodes = w.network.nodes;
  const double sigma = w.spec.params.sigma;
  // Brute force over edge pairs with a coarse bounding-box reject.
  std::vector<std::size_t> edges;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].parent.valid())
      edges.push_back(i);
  std::size_t checked = 0;
  for (std::size_t a = 0; a < edges.size(); ++a) {
    const RiverNode& ea = nodes[edges[a]];
    const geometry::Vec2 a0 = nodes[ea.parent.index()].position, a1 = ea.position;
    for (std::size_t b = a + 1; b < edges.size(); ++b) {
      const RiverNode& eb = nodes[edges[b]];
      const geometry::Vec2 b0 = nodes[eb.parent.index()].position, b1 = eb.position;
      if (std::abs(a1.x - b1.x) > 3 * sigma || std::abs(a1.y - b1.y) > 3 * sigma)
        continue;
      const std::size_t ia = edges[a], ib = edges[b];
      const bool adjacent =
          ea.parent == eb.parent || ea.parent.index() == ib || eb.parent.index() == ia;
      if (adjacent)
        continue;
      ++checked;
      ASSERT_GT(geometry::segmentSegmentDistance(a0, a1, b0, b1), sigma)
          << "edges below nodes " << ia << " and " << ib;
    }
  }
  EXPECT_GT(checked, edges.size());
}

TEST_P(NetworkInvariants, EveryNodeIsHigherThanItsParentAndReachesAMouth) {
  const GrownWorld& w = grown();
  const auto& nodes = w.network.nodes;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const RiverNode& n = nodes[i];
    ASSERT_LE(n.children.size(), 2u) << "binary confluences";
    for (NodeId c : n.children)
      ASSERT_EQ(nodes[c.index()].parent.index(), i);
    if (!n.parent.valid()) {
      EXPECT_EQ(n.elevation, 0.0);
      continue;
    }
    ASSERT_LT(n.parent.index(), i) << "parents precede children";
    const RiverNode& p = nodes[n.parent.index()];
    ASSERT_GT(n.elevation, p.elevation);
    ASSERT_NEAR(geometry::distance(n.position, p.position), w.spec.params.edgeLength, 1e-6);
    ASSERT_EQ(n.tree, p.tree);
  }
  // Walking downstream from any node ends at the mouth of its tree.
  for (std::size_t i = 0; i < nodes.size(); i += 7) {
    std::size_t cur = i, steps = 0;
    while (nodes[cur].parent.valid() && steps++ <= nodes.size())
      cur = nodes[cur].parent.index();
    ASSERT_EQ(w.network.mouths[nodes[i].tree].node.index(), cur);
  }
}

TEST_P(NetworkInvariants, SlopesBetweenNeighboursStayBelowKappa) {
  const GrownWorld& w = grown();
  const auto& nodes = w.network.nodes;
  const double kappa = w.spec.params.kappa;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const RiverNode& n = nodes[i];
    if (!n.parent.valid())
      continue;
    const RiverNode& p = nodes[n.parent.index()];
    ASSERT_LT((n.elevation - p.elevation) / w.spec.params.edgeLength, kappa);
  }
}

INSTANTIATE_TEST_SUITE_P(
    GrowersAndWorlds, NetworkInvariants,
    ::testing::Combine(::testing::Values(NetworkGrower::kGrammar, NetworkGrower::kDla),
                       ::testing::Values("default", "mallorca")),
    [](const auto& tested) {
      return std::string(std::get<0>(tested.param) == NetworkGrower::kDla ? "dla_" : "grammar_") +
             std::get<1>(tested.param);
    });

/// Whether two networks' node positions differ (or their sizes).
bool differ(const RiverNetwork& a, const RiverNetwork& b) {
  bool differs = a.nodes.size() != b.nodes.size();
  for (std::size_t i = 0; !differs && i < a.nodes.size(); ++i)
    differs = !(a.nodes[i].position == b.nodes[i].position);
  return differs;
}

/// Each grower: the same seed gives the same graph bit for bit, another seed another graph.
class GrowerSeeds : public ::testing::TestWithParam<NetworkGrower> {};

TEST_P(GrowerSeeds, SameSeedGivesIdenticalGraph) {
  const GrownWorld a = grow(test_support::defaultIslandSpec(7), GetParam());
  const GrownWorld b = grow(test_support::defaultIslandSpec(7), GetParam());
  ASSERT_EQ(a.network.nodes.size(), b.network.nodes.size());
  for (std::size_t i = 0; i < a.network.nodes.size(); ++i) {
    const RiverNode &x = a.network.nodes[i], &y = b.network.nodes[i];
    ASSERT_EQ(std::memcmp(&x.position, &y.position, sizeof x.position), 0);
    ASSERT_EQ(std::memcmp(&x.elevation, &y.elevation, sizeof x.elevation), 0);
    ASSERT_EQ(x.parent, y.parent);
    ASSERT_EQ(x.priority, y.priority);
    ASSERT_EQ(x.strahler, y.strahler);
  }
}

TEST_P(GrowerSeeds, DifferentSeedsGiveDifferentGraphs) {
  EXPECT_TRUE(differ(grow(test_support::defaultIslandSpec(1), GetParam()).network,
                     grow(test_support::defaultIslandSpec(2), GetParam()).network));
}

INSTANTIATE_TEST_SUITE_P(Growers, GrowerSeeds,
                         ::testing::Values(NetworkGrower::kGrammar, NetworkGrower::kDla),
                         [](const auto& tested) {
                           return std::string(tested.param == NetworkGrower::kDla ? "dla"
                                                                                  : "grammar");
                         });

TEST(NetworkGrowth, TheGrowersGiveDifferentGraphs) {
  EXPECT_TRUE(differ(grow(test_support::defaultIslandSpec(1)).network,
                     grow(test_support::defaultIslandSpec(1), NetworkGrower::kDla).network));
}

TEST(NetworkGrowth, RefusesWorldsWithTooManyNodes) {
  input::WorldSpec spec = test_support::corsicaSpec(); // 8,700 km² at 50 m edges: ~4.8M nodes
  spec.params.edgeLength = 50.0;
  spec.params.sigma = 36.0;
  geometry::PolygonIndex land(spec.land);
  auto net = generateNetwork(spec, land);
  ASSERT_FALSE(net.ok());
  EXPECT_EQ(net.error().code, base::ErrorCode::kLimitExceeded);
  EXPECT_NE(net.error().message.find("river nodes"), std::string::npos);
}

} // namespace
} // namespace strahler::network

namespace strahler::network {
namespace {

/// A constraint image of one value covering the whole land (the paper's Figure 17).
input::ConstraintMap uniformConstraint(const input::WorldSpec& spec, input::ConstraintKind kind,
                                       float value) {
  geometry::Aabb box;
  for (const geometry::Polygon& p : spec.landLonLat)
    box.add(geometry::bounds(p.outer));
  input::ConstraintMap map;
  map.kind = kind;
  map.bounds = {box.min.x - 0.1, box.min.y - 0.1, box.max.x + 0.1, box.max.y + 0.1};
  map.image.width = map.image.height = 4;
  map.image.pixels.assign(16, value);
  return map;
}

double maxRise(const RiverNetwork& network) {
  double highest = 0.0;
  for (const RiverNode& n : network.nodes) {
    if (n.parent.valid())
      highest = std::max(highest, n.elevation - network.node(n.parent).elevation);
  }
  return highest;
}

TEST(NetworkGrowth, FlatConstraintImageGivesGentleRivers) {
  input::WorldSpec spec = test_support::defaultIslandSpec();
  spec.constraints.push_back(
      uniformConstraint(spec, input::ConstraintKind::kMountainousness, 0.0f));
  const GrownWorld w = grow(std::move(spec));
  const input::Params& p = w.spec.params;
  EXPECT_LE(maxRise(w.network), p.edgeLength * p.slopeMin * (1.0 + p.slopeJitter) + 1e-9);
}

TEST(NetworkGrowth, SteepRiverSlopeImageGivesSteepRivers) {
  input::WorldSpec spec = test_support::defaultIslandSpec();
  spec.constraints.push_back(uniformConstraint(spec, input::ConstraintKind::kRiverSlope, 1.0f));
  const GrownWorld w = grow(std::move(spec));
  const input::Params& p = w.spec.params;
  for (const RiverNode& n : w.network.nodes) {
    if (!n.parent.valid())
      continue;
    ASSERT_GE(n.elevation - w.network.node(n.parent).elevation,
              p.edgeLength * p.slopeMax * (1.0 - p.slopeJitter) - 1e-9);
  }
}

} // namespace
} // namespace strahler::network
