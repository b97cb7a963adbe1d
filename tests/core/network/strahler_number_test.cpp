#include "strahler/network/river_network.h"

#include <gtest/gtest.h>

namespace strahler::network {
namespace {

/// Builds a network from parent indices (-1 for a mouth); parents must precede children.
RiverNetwork treeFromParents(const std::vector<int>& parents) {
  RiverNetwork net;
  for (std::size_t i = 0; i < parents.size(); ++i) {
    RiverNode node;
    node.position = {double(i), 0.0};
    if (parents[i] >= 0) {
      node.parent = NodeId(static_cast<std::uint32_t>(parents[i]));
      net.nodes[static_cast<std::size_t>(parents[i])].children.push_back(NodeId(std::uint32_t(i)));
    } else {
      net.mouths.push_back({NodeId(std::uint32_t(i)), {1, 0}, false});
    }
    net.nodes.push_back(node);
  }
  computeStrahlerNumbers(net);
  return net;
}

std::vector<int> numbers(const RiverNetwork& net) {
  std::vector<int> out;
  for (const RiverNode& n : net.nodes)
    out.push_back(n.strahler);
  return out;
}

TEST(StrahlerNumbers, SingleChainIsOrderOne) {
  EXPECT_EQ(numbers(treeFromParents({-1, 0, 1, 2})), (std::vector<int>{1, 1, 1, 1}));
}

TEST(StrahlerNumbers, TwoEqualTributariesRaiseTheOrder) {
  // 0 <- 1 <- {2, 3}
  EXPECT_EQ(numbers(treeFromParents({-1, 0, 1, 1})), (std::vector<int>{2, 2, 1, 1}));
}

TEST(StrahlerNumbers, UnequalTributariesKeepTheHigherOrder) {
  // 0 <- {1, 2}; 1 <- {3, 4}: node 1 is order 2, node 2 order 1, so 0 stays 2.
  EXPECT_EQ(numbers(treeFromParents({-1, 0, 0, 1, 1})), (std::vector<int>{2, 2, 1, 1, 1}));
}

TEST(StrahlerNumbers, FullBinaryTreeOfDepthThreeIsOrderThree) {
  // 0 <- {1, 2}; 1 <- {3, 4}; 2 <- {5, 6}
  EXPECT_EQ(numbers(treeFromParents({-1, 0, 0, 1, 1, 2, 2})),
            (std::vector<int>{3, 2, 2, 1, 1, 1, 1}));
}

TEST(StrahlerNumbers, ThreeTributariesOfEqualOrderRaiseByOne) {
  EXPECT_EQ(numbers(treeFromParents({-1, 0, 0, 0})), (std::vector<int>{2, 1, 1, 1}));
}

TEST(StrahlerNumbers, HistogramCountsNodesPerOrder) {
  const auto histogram = strahlerHistogram(treeFromParents({-1, 0, 0, 1, 1, 2, 2}));
  ASSERT_EQ(histogram.size(), 4u);
  EXPECT_EQ(histogram[1], 4u);
  EXPECT_EQ(histogram[2], 2u);
  EXPECT_EQ(histogram[3], 1u);
}

} // namespace
} // namespace strahler::network
