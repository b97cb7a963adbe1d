#pragma once

#include "strahler/geometry/grid_index.h"
#include "strahler/input/world_spec.h"
#include "strahler/network/drawn_rivers.h"

#include <optional>
#include <vector>

namespace strahler::network::detail {

/// Where a node sits on a drawn river: the river's index and the arc lengths of the chain
/// nodes on either side of it (the stretch of the line its own edges run along).
struct ChainPlace {
  int river = -1;  ///< Index in the spec's features.rivers; -1: not a chain node.
  double lo = 0.0; ///< Arc length (from the source) of the node upstream of it, or its own.
  double hi = 0.0; ///< Arc length of the node downstream of it, or its own.
};

/// The drawn lines grammar edges must keep clear of: ridgelines (never crossed, δ away) and
/// drawn rivers (σ away, as the grower's own edges; a tributary of a chain node only must not
/// cross the line next to that node).
class Barriers {
public:
  /// The ridges of `spec.features` and the drawn rivers of `courses` (none where nullopt).
  Barriers(const input::WorldSpec& spec, const geometry::PolygonIndex& land,
           const std::vector<std::optional<DrawnCourse>>& courses);

  /// True when nothing was drawn that edges must keep clear of.
  bool empty() const noexcept { return pieces_.empty(); }
  /// Whether the edge [from, to] keeps clear of every drawn line; `at` is where `from` sits
  /// on a drawn river (river −1 when it does not).
  bool allows(geometry::Vec2 from, geometry::Vec2 to, const ChainPlace& at) const;
  /// Whether point p lies more than σ from every drawn river.
  bool farFromRivers(geometry::Vec2 p) const;

private:
  struct Piece {
    geometry::Vec2 a, b;
    double s0 = 0.0, s1 = 0.0; // arc lengths of a and b along a drawn river
    int river = -1;            // -1: a piece of a ridgeline
  };
  void add(const Piece& piece);

  double sigma_;
  double ridgeClearance_;
  std::vector<Piece> pieces_;
  geometry::GridIndex grid_;
};

} // namespace strahler::network::detail
