#pragma once

#include "strahler/construction/world.h"
#include "strahler/network/river_network.h"

#include <cstddef>
#include <limits>
#include <vector>

namespace strahler::quality {

/// A least-squares fit of log10 L = log10 c + h·log10 A (Hack's law L = c·A^h; L in km, A in
/// km²).
struct HackFit {
  double exponent = std::numeric_limits<double>::quiet_NaN();    ///< h; NaN with < 2 points.
  double coefficient = std::numeric_limits<double>::quiet_NaN(); ///< c, km per km²^h.
  double r2 = std::numeric_limits<double>::quiet_NaN();          ///< Coefficient of determination.
  std::size_t points = 0;                                        ///< Points fitted.
};

/// Hack's law of a river network, fitted two ways.
struct HackLaw {
  HackFit nodes;   ///< Over every node with L > 0 (every point along every stream).
  HackFit outlets; ///< Over the mouths with L > 0 (one point per basin).
};

/// Per node: the main-stream length L, metres: the length along the graph of the longest path
/// from the node up to a source (a node without children, whose L is 0).
std::vector<double> mainStreamLengthsM(const network::RiverNetwork& network);

/// Hack's law of `network` with per-node drainage areas `areaKm2` (a node's block plus every
/// block upstream): points (A, L) of nodes with L > 0 and A > 0.
HackLaw fitHackLaw(const network::RiverNetwork& network, const std::vector<double>& areaKm2);

/// The drainage area (km²) of every node of the world's network, as the generator computes it:
/// the node's Voronoi block clipped to the land plus every block upstream. Empty if the
/// blocks cannot be rebuilt (they always can for a world the generator made).
std::vector<double> networkDrainageAreasKm2(const construction::World& world);

} // namespace strahler::quality
