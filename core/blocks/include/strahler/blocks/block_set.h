#pragma once

#include "strahler/base/result.h"
#include "strahler/base/strong_id.h"
#include "strahler/geometry/polygon.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/network/river_network.h"

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace strahler::blocks {

using base::NodeId;

/// A vertex of the Voronoi diagram of the river nodes: equidistant from three nodes. These
/// are the ridge vertices q of Section 5.1.
struct VoronoiVertex {
  geometry::Vec2 position;       ///< Circumcentre of the three nodes, local metres.
  std::array<NodeId, 3> sites{}; ///< The three river nodes whose cells meet here.
  double radius = 0.0;           ///< d: distance from the vertex to each of its sites.
};

/// Marks a cell corner that is not a Voronoi vertex (made by clipping to the frame box).
inline constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

/// The terrain block of one river node: its Voronoi cell, clipped to the land.
struct Block {
  /// The river node this block belongs to (same index).
  NodeId node;
  /// Voronoi cell clipped to the frame box: convex, counter-clockwise, holds its node.
  geometry::Ring cell;
  /// Per corner of `cell`: index into BlockSet::vertices, or kNoVertex.
  std::vector<std::uint32_t> cellVertices;
  /// Per edge cell[i]→cell[i+1]: the node across it, or invalid on the frame.
  std::vector<NodeId> neighbours;
  /// cell ∩ land: one polygon per land polygon met (outer CCW, lake holes CW). As with
  /// geometry::clipToConvex, parts the cell cuts apart may stay joined by zero-width bridges
  /// along the cell border.
  geometry::MultiPolygon region;
  /// Area of `region`, m².
  double area = 0.0;
};

/// The segmentation V = {V_i} of the land into blocks (Section 5.1).
struct BlockSet {
  std::vector<Block> blocks;           ///< blocks[i] belongs to network node i.
  std::vector<VoronoiVertex> vertices; ///< Every finite Voronoi vertex.
  geometry::Aabb frame; ///< Box the cells were clipped to: land and nodes, plus a margin.
};

/// Builds the Voronoi blocks of every node of `network`, clipped to `land`. Any number of nodes
/// works (collinear ones too). Fails with kInvalidInput if two nodes coincide or a position is
/// not finite. Deterministic: the same input gives bit-identical output.
base::Result<BlockSet> buildBlocks(const network::RiverNetwork& network,
                                   const geometry::PolygonIndex& land);

} // namespace strahler::blocks
