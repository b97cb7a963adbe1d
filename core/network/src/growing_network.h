#pragma once

#include "barriers.h"

#include "strahler/geometry/grid_index.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/input/world_spec.h"
#include "strahler/network/drawn_rivers.h"
#include "strahler/network/mouth_placement.h"
#include "strahler/network/relief_law.h"
#include "strahler/network/river_network.h"

#include <optional>
#include <vector>

namespace strahler::network::detail {

/// The least rise of a child above its parent, m: children are strictly higher.
inline constexpr double kMinRise = 0.01;

/// A river network under construction, what both growers (the grammar, DLA) build on: the
/// nodes with their flow directions and places on drawn rivers, the grid indices of nodes and
/// edges, the drawn rivers' chains, and the tests every new edge passes (Section 4.2.2: in Ω
/// and δ from Γ, σ from non-adjacent edges, slopes below κ, the drawn barriers). A grower
/// derives from it; nodeAdded() tells it of every node added.
class GrowingNetwork {
public:
  /// An empty network over `land` with `spec`'s parameters, relief law and drawn features.
  GrowingNetwork(const input::WorldSpec& spec, const geometry::PolygonIndex& land);
  virtual ~GrowingNetwork() = default;
  GrowingNetwork(const GrowingNetwork&) = delete;
  GrowingNetwork& operator=(const GrowingNetwork&) = delete;

protected:
  /// Called after every node is added (the grammar makes it a candidate).
  virtual void nodeAdded(NodeId) {}

  /// Adds node p (elevation z, priority ≥ 1, unit flow direction `dir`) below `parent`
  /// (invalid for a mouth), indexing it and its edge.
  NodeId addNode(geometry::Vec2 p, double z, NodeId parent, int priority, geometry::Vec2 dir);
  /// Adds mouth `m` as the root of a new tree, with `priority`.
  void addMouth(const MouthSite& m, int priority);
  /// Adds the chain of drawn river `river` above its mouth node: one node per chain point of
  /// its course, exactly on the line, each the child of the one below it, with `priority` and
  /// the relief law's rise over the step (so monotone upstream). Growth goes around it.
  void addChain(NodeId mouth, int river, int priority);

  /// The geometric tests for a new node p (elevation z) below `parentId`.
  bool valid(NodeId parentId, geometry::Vec2 p, double z) const;
  /// Whether the edge [from, p] stays more than σ from every edge not adjacent to node `from`
  /// (`fromId`; invalid for a point that is not yet a node).
  bool clearOfEdges(geometry::Vec2 from, geometry::Vec2 p, NodeId fromId) const;
  /// Whether p at elevation z rises less than κ per metre toward every node within three edges.
  bool slopesBelowKappa(geometry::Vec2 p, double z) const;

  const input::Params& params_;
  const geometry::PolygonIndex& land_;
  ReliefLaw relief_;
  geometry::GridIndex edges_;              ///< Edge [parent(c), c] registered under child id c.
  geometry::GridIndex nodeGrid_;           ///< Every node, cells of side e.
  std::vector<geometry::Vec2> directions_; ///< Per node: unit flow direction, upstream.
  std::vector<std::optional<DrawnCourse>> courses_; ///< Drawn rivers, by feature index.
  Barriers barriers_;                               ///< Ridgelines and drawn rivers.
  std::vector<ChainPlace> places_;                  ///< Per node: its place on a drawn river.
  RiverNetwork network_;                            ///< What is grown.
};

} // namespace strahler::network::detail
