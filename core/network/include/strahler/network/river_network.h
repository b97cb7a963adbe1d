#pragma once

#include "strahler/base/strong_id.h"
#include "strahler/geometry/vec2.h"

#include <cstdint>
#include <vector>

namespace strahler::network {

using base::NodeId;

/// One node of the river graph: a point of a river, higher than the node it drains into.
struct RiverNode {
  geometry::Vec2 position;      ///< Local frame, metres.
  double elevation = 0.0;       ///< Metres above sea level; mouths are at 0.
  NodeId parent;                ///< The node downstream; invalid for a mouth.
  std::vector<NodeId> children; ///< Nodes upstream that drain into this one.
  int priority = 1;             ///< Grammar priority index s (Section 4.2.2).
  int strahler = 1;             ///< Horton-Strahler number of the final tree.
  std::uint32_t tree = 0;       ///< Index of the tree (= of its mouth in RiverNetwork::mouths).
};

/// A river mouth: the root of one tree, on the coast or a lake shore.
struct Mouth {
  NodeId node;           ///< The root node.
  geometry::Vec2 inward; ///< Unit vector pointing inland, perpendicular to the shore.
  bool onLake = false;   ///< True when the mouth is on a lake shore (a polygon hole).
};

/// The river graph G = {G_i}: a forest of trees rooted at mouths. Nodes are stored so that
/// every parent comes before its children (creation order of the growth).
struct RiverNetwork {
  std::vector<RiverNode> nodes;
  std::vector<Mouth> mouths;
  double edgeLength = 0.0; ///< e used to grow it (every edge has this length).

  /// The node with id `id`.
  const RiverNode& node(NodeId id) const { return nodes[id.index()]; }
  /// Number of edges (every node but the mouths has exactly one, to its parent).
  std::size_t edgeCount() const noexcept { return nodes.size() - mouths.size(); }
  /// Total river length in metres.
  double totalLength() const noexcept;
};

/// Recomputes every node's Horton-Strahler number from the tree shape: 1 for a leaf; the
/// children's maximum k if only one child has k; k + 1 if several do.
void computeStrahlerNumbers(RiverNetwork& network);

/// Number of nodes per Strahler number; index 0 unused.
std::vector<std::size_t> strahlerHistogram(const RiverNetwork& network);

} // namespace strahler::network
