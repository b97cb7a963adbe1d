#include "strahler/quality/horton.h"

#include <gtest/gtest.h>

#include <cmath>

namespace strahler::quality {
namespace {

using network::NodeId;
using network::RiverNetwork;
using network::RiverNode;

/// Builds river trees node by node; every child is `length` metres east of its parent.
class TreeBuilder {
public:
  /// Adds a mouth (a root) and returns it.
  NodeId mouth() {
    const NodeId id = next();
    RiverNode node;
    node.position = {0.0, 1000.0 * double(net_.mouths.size())};
    net_.mouths.push_back({id, {1.0, 0.0}, false});
    net_.nodes.push_back(node);
    return id;
  }
  /// Adds a node draining into `parent` through an edge of `length` metres.
  NodeId child(NodeId parent, double length = 100.0) {
    const NodeId id = next();
    RiverNode node;
    node.parent = parent;
    node.position = net_.node(parent).position + geometry::Vec2{length, 0.0};
    net_.nodes[parent.index()].children.push_back(id);
    net_.nodes.push_back(node);
    return id;
  }
  /// The network with Strahler numbers computed.
  RiverNetwork finish() {
    network::computeStrahlerNumbers(net_);
    return net_;
  }

private:
  NodeId next() const { return NodeId(std::uint32_t(net_.nodes.size())); }
  RiverNetwork net_;
};

/// Two leaves on `node`.
void fork(TreeBuilder& tree, NodeId node) {
  tree.child(node);
  tree.child(node);
}

TEST(Horton, PerfectBinaryTreeOfOrderThree) {
  TreeBuilder tree;
  const NodeId trunk = tree.child(tree.mouth());
  const NodeId left = tree.child(trunk), right = tree.child(trunk);
  fork(tree, left);
  fork(tree, right);
  const HortonStatistics stats = hortonStatistics(tree.finish());
  EXPECT_EQ(stats.streamCount, (std::vector<std::size_t>{0, 4, 2, 1}));
  EXPECT_EQ(stats.meanStreamLength, (std::vector<double>{0.0, 100.0, 100.0, 100.0}));
  EXPECT_NEAR(stats.bifurcationRatio, 2.0, 1e-12);
  EXPECT_NEAR(stats.lengthRatio, 1.0, 1e-12);
}

TEST(Horton, FractalDimensionIsLnRbOverLnRl) {
  // A binary tree whose stream lengths double with the order: Rb = Rl = 2, so D = 1.
  TreeBuilder tree;
  const NodeId trunk = tree.child(tree.mouth(), 400.0);
  const NodeId left = tree.child(trunk, 200.0), right = tree.child(trunk, 200.0);
  fork(tree, left);
  fork(tree, right);
  const HortonStatistics stats = hortonStatistics(tree.finish());
  EXPECT_NEAR(stats.bifurcationRatio, 2.0, 1e-12);
  EXPECT_NEAR(stats.lengthRatio, 2.0, 1e-12);
  EXPECT_NEAR(stats.fractalDimension, 1.0, 1e-12);
}

TEST(Horton, FractalDimensionIsUndefinedWhenLengthsDoNotGrow) {
  TreeBuilder tree;
  fork(tree, tree.child(tree.mouth())); // every stream 100 m: Rl = 1
  EXPECT_TRUE(std::isnan(hortonStatistics(tree.finish()).fractalDimension));
}

TEST(Horton, StreamsFollowChainsAndIgnoreLowerTributaries) {
  // mouth <- t1 <- t2 <- {x <- x2 <- x3, y}; t1 also receives z (order 1).
  TreeBuilder tree;
  const NodeId t1 = tree.child(tree.mouth());
  const NodeId t2 = tree.child(t1, 200.0);
  tree.child(tree.child(tree.child(t2)));
  tree.child(t2, 50.0);
  tree.child(t1, 150.0);
  const HortonStatistics stats = hortonStatistics(tree.finish());
  ASSERT_EQ(stats.streamCount, (std::vector<std::size_t>{0, 3, 1}));
  EXPECT_NEAR(stats.meanStreamLength[1], (300.0 + 50.0 + 150.0) / 3.0, 1e-9);
  EXPECT_NEAR(stats.meanStreamLength[2], 300.0, 1e-9) << "t2 -> t1 -> mouth is one stream";
  EXPECT_NEAR(stats.bifurcationRatio, 3.0, 1e-12);
  EXPECT_NEAR(stats.lengthRatio, 300.0 / (500.0 / 3.0), 1e-12);
  EXPECT_NEAR(stats.fractalDimension, std::log(3.0) / std::log(1.8), 1e-12);
}

TEST(Horton, RatiosComeFromALeastSquaresFit) {
  // N = {8, 3, 1}: the fitted slope of ln N over k = 1, 2, 3 is -ln(8) / 2, so Rb = sqrt(8),
  // although the successive ratios are 8/3 and 3.
  TreeBuilder tree;
  const NodeId a = tree.child(tree.mouth());
  const NodeId b = tree.child(a);
  const NodeId c = tree.child(b), d = tree.child(b), e = tree.child(a);
  tree.child(a); // order-1 tributary of the order-3 stream
  fork(tree, c);
  tree.child(c);
  fork(tree, d);
  fork(tree, e);
  const RiverNetwork net = tree.finish();
  ASSERT_EQ(net.node(a).strahler, 3);
  const HortonStatistics stats = hortonStatistics(net);
  ASSERT_EQ(stats.streamCount, (std::vector<std::size_t>{0, 8, 3, 1}));
  EXPECT_NEAR(stats.bifurcationRatio, std::sqrt(8.0), 1e-12);
  EXPECT_NEAR(stats.meanStreamLength[3], 200.0, 1e-9);
  // ln L = {ln 100, ln 100, ln 200}: slope (ln 200 - ln 100) / 2.
  EXPECT_NEAR(stats.lengthRatio, std::sqrt(2.0), 1e-12);
}

TEST(Horton, SingleChainHasOneOrderAndNoRatios) {
  TreeBuilder tree;
  tree.child(tree.child(tree.child(tree.mouth())));
  const HortonStatistics stats = hortonStatistics(tree.finish());
  EXPECT_EQ(stats.streamCount, (std::vector<std::size_t>{0, 1}));
  EXPECT_NEAR(stats.meanStreamLength[1], 300.0, 1e-9);
  EXPECT_TRUE(std::isnan(stats.bifurcationRatio));
  EXPECT_TRUE(std::isnan(stats.lengthRatio));
}

TEST(Horton, ForestCountsEveryTree) {
  TreeBuilder tree;
  fork(tree, tree.child(tree.mouth()));
  fork(tree, tree.child(tree.mouth()));
  tree.child(tree.mouth());
  const HortonStatistics stats = hortonStatistics(tree.finish());
  EXPECT_EQ(stats.streamCount, (std::vector<std::size_t>{0, 5, 2}));
  EXPECT_NEAR(stats.bifurcationRatio, 2.5, 1e-12);
}

TEST(Horton, NetworkWithoutEdgesHasNoStreams) {
  TreeBuilder tree;
  tree.mouth();
  const HortonStatistics stats = hortonStatistics(tree.finish());
  EXPECT_EQ(stats.streamCount, (std::vector<std::size_t>{0}));
  EXPECT_TRUE(std::isnan(stats.bifurcationRatio));
  EXPECT_TRUE(std::isnan(hortonStatistics(RiverNetwork{}).lengthRatio));
}

} // namespace
} // namespace strahler::quality
