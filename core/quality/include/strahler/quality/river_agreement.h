#pragma once

#include "strahler/construction/world.h"
#include "strahler/quality/drainage.h"
#include "strahler/quality/flow_field.h"
#include "strahler/quality/relief.h"

#include <array>
#include <limits>
#include <vector>

namespace strahler::quality {

/// Distance (metres) within which a D8 channel and a world river centreline agree.
inline constexpr double kAgreementDistanceM = 150.0;

/// Distance (metres) from a river within which every land point should lie (issue 16's
/// coverage target).
inline constexpr double kCoverageDistanceM = 3000.0;

/// The value of a figure that was not measured.
inline constexpr double kUnmeasured = std::numeric_limits<double>::quiet_NaN();

/// Relief figures that compare the terrain with the world's own river network; a
/// default-constructed one (no world, e.g. a DEM) has every figure NaN.
struct NetworkReliefFigures {
  /// Share of the D8 channel cells (area ≥ 1 km²) within 150 m of a river centreline; NaN
  /// without channel cells. Distances between cell centres (within half a cell diagonal).
  double channelsNearRivers = kUnmeasured;
  /// Share of the centreline length of rivers of Strahler order ≥ 2 within 150 m of a D8
  /// channel cell (sampled every half cell, each piece at its nearest cell); NaN without such
  /// rivers.
  double riversNearChannels = kUnmeasured;
  /// Coverage: the 99th percentile and the greatest distance (m) from a land cell to the
  /// nearest cell a river centreline crosses, and the share of land cells farther than
  /// kCoverageDistanceM; NaN without land.
  double riverDistanceP99M = kUnmeasured, riverDistanceMaxM = kUnmeasured,
         fartherThanCoverageFraction = kUnmeasured;
  /// The centre of the land cell farthest from the rivers (local metres).
  geometry::Vec2 farthestFromRivers{kUnmeasured, kUnmeasured};
  /// Confluences of the river graph: nodes with ≥ 2 children, and those with ≥ 3.
  ConfluenceCount networkConfluences;
  /// Mean sinuosity (curve length / distance between its ends) of the river primitives of
  /// each Rosgen type: B, E, D, D-delta; NaN for a type without primitives.
  double sinuosityB = kUnmeasured, sinuosityE = kUnmeasured, sinuosityD = kUnmeasured,
         sinuosityDelta = kUnmeasured;
};

/// Compares `world`'s rivers with the D8 flow `flow` of `raster` (a rasterizeWorld raster,
/// unburnt, so that the terrain's own channels are measured).
NetworkReliefFigures compareWithRivers(const construction::World& world, const HeightRaster& raster,
                                       const FlowField& flow);

/// The river graph's confluences (nodes with ≥ 2 children; ≥ 3 among them).
ConfluenceCount countNetworkConfluences(const network::RiverNetwork& network);

/// Mean sinuosity per Rosgen type, in the order B, E, D, D-delta (NaN for an absent type).
std::array<double, 4> meanSinuosity(const std::vector<primitives::RiverPrimitive>& rivers);

} // namespace strahler::quality
