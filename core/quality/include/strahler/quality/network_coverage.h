#pragma once

#include "strahler/geometry/polygon_index.h"
#include "strahler/network/river_network.h"

#include <limits>

namespace strahler::quality {

/// How far the land lies from the river graph: the coverage of a network (issue 30).
struct NetworkCoverage {
  /// Distance (m) from the land point farthest from every river edge to the nearest edge,
  /// measured at cell centres; NaN without land cells or without edges.
  double farthestM = std::numeric_limits<double>::quiet_NaN();
  geometry::Vec2 farthestAt; ///< That land point, local metres.
  double cellSize = 0.0;     ///< Side of the measuring grid's cells, m.
  double fartherThan3KmFraction = std::numeric_limits<double>::quiet_NaN(); ///< Land share.
};

/// The coverage of `network` over `land`: a grid of `cellSize`-metre cells (coarser when the
/// land would need more than 2^24 cells) whose cells crossed by an edge count as river; every
/// cell whose centre is in the land is measured by its exact distance to those cells' centres.
/// The error is at most one cell's diagonal.
NetworkCoverage networkCoverage(const network::RiverNetwork& network,
                                const geometry::PolygonIndex& land, double cellSize = 100.0);

} // namespace strahler::quality
