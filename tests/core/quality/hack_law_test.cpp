#include "strahler/quality/hack_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace strahler::quality {
namespace {

using network::NodeId;
using network::RiverNetwork;
using network::RiverNode;

/// Adds a node `length` metres east of `parent` (a mouth when parent is invalid).
NodeId addNode(RiverNetwork& net, NodeId parent, double length) {
  const NodeId id(std::uint32_t(net.nodes.size()));
  RiverNode node;
  node.parent = parent;
  if (parent.valid()) {
    node.position = net.node(parent).position + geometry::Vec2{length, 0.0};
    net.nodes[parent.index()].children.push_back(id);
  } else {
    node.position = {0.0, 1000.0 * double(net.mouths.size())};
    net.mouths.push_back({id, {1.0, 0.0}, false});
  }
  net.nodes.push_back(node);
  return id;
}

TEST(HackLaw, MainStreamLengthFollowsTheLongestBranch) {
  // mouth <- a <- {b <- c, d}: edges 100, 200, 300 (b), 50 (c), 400 (d).
  RiverNetwork net;
  const NodeId mouth = addNode(net, {}, 0);
  const NodeId a = addNode(net, mouth, 100);
  const NodeId b = addNode(net, a, 300);
  const NodeId c = addNode(net, b, 50);
  const NodeId d = addNode(net, a, 400);
  const std::vector<double> l = mainStreamLengthsM(net);
  EXPECT_DOUBLE_EQ(l[c.index()], 0.0);
  EXPECT_DOUBLE_EQ(l[d.index()], 0.0);
  EXPECT_DOUBLE_EQ(l[b.index()], 50.0);
  EXPECT_DOUBLE_EQ(l[a.index()], 400.0) << "d's 400 m beats b's 350 m";
  EXPECT_DOUBLE_EQ(l[mouth.index()], 500.0);
}

TEST(HackLaw, RecoversAnExactPowerLaw) {
  // Two chains of 10 edges of 250 m; every node's area makes L = 1.4 A^0.57 exactly.
  RiverNetwork net;
  for (int chain = 0; chain < 2; ++chain) {
    NodeId at = addNode(net, {}, 0);
    for (int i = 0; i < 10; ++i)
      at = addNode(net, at, 250.0 + 100.0 * chain);
  }
  const std::vector<double> length = mainStreamLengthsM(net);
  std::vector<double> area;
  for (double l : length)
    area.push_back(l > 0 ? std::pow(l * 1e-3 / 1.4, 1.0 / 0.57) : 0.01);
  const HackLaw hack = fitHackLaw(net, area);
  EXPECT_EQ(hack.nodes.points, 20u) << "the two sources have L = 0";
  EXPECT_NEAR(hack.nodes.exponent, 0.57, 1e-9);
  EXPECT_NEAR(hack.nodes.coefficient, 1.4, 1e-9);
  EXPECT_NEAR(hack.nodes.r2, 1.0, 1e-9);
  EXPECT_EQ(hack.outlets.points, 2u);
  EXPECT_NEAR(hack.outlets.exponent, 0.57, 1e-9);
}

TEST(HackLaw, UndefinedWithFewerThanTwoPoints) {
  RiverNetwork net;
  addNode(net, addNode(net, {}, 0), 100);
  const HackLaw hack = fitHackLaw(net, {2.0, 1.0});
  EXPECT_EQ(hack.nodes.points, 1u);
  EXPECT_TRUE(std::isnan(hack.nodes.exponent));
  EXPECT_TRUE(std::isnan(hack.outlets.exponent));
}

} // namespace
} // namespace strahler::quality
