#pragma once

#include "strahler/quality/drainage.h"
#include "strahler/quality/flow_field.h"

#include <cstddef>
#include <limits>

namespace strahler::quality {

/// Least-squares fit of log10(S) = a − θ·log10(A) over binned channel cells.
struct SlopeAreaFit {
  double theta = 0.0;   ///< Concavity θ; NaN with fewer than 2 bins or no spread in A.
  double r2 = 0.0;      ///< Coefficient of determination of the fit; NaN like theta.
  std::size_t bins = 0; ///< Bins used.
};

/// Distribution of the land slope (central differences at the cell size).
struct SlopeStatistics {
  double p50Deg = 0.0;        ///< Median slope, degrees; NaN without cells.
  double p90Deg = 0.0;        ///< 90th percentile, degrees (linear interpolation).
  double p99Deg = 0.0;        ///< 99th percentile, degrees.
  double steeperThan45 = 0.0; ///< Share of the cells steeper than 45°, 0..1.
  std::size_t cells = 0;      ///< Land cells whose 4 neighbours are land.
};

/// Confluences of the D8 channel network (channel: upstream area ≥ 1 km²).
struct ConfluenceCount {
  std::size_t confluences = 0; ///< Channel cells with ≥ 2 channel inflows.
  std::size_t threeOrMore = 0; ///< Those with ≥ 3.
  /// threeOrMore / confluences; NaN without confluences.
  double shareThreeOrMore = std::numeric_limits<double>::quiet_NaN();
};

/// Every relief figure that needs only a height raster.
struct ReliefFigures {
  SlopeAreaFit slopeArea;
  SlopeStatistics slopes;
  ConfluenceCount confluences;
  double drainageDensity01 = 0.0; ///< km of D8 channel (≥ 0.1 km²) per km² of land; NaN no land.
  double drainageDensity1 = 0.0;  ///< The same for channels ≥ 1 km².
  double dissection = 0.0;        ///< See measureDissection; NaN without interior cells.
  double highest = 0.0;           ///< Greatest height of a land cell, m; NaN without land.
  std::size_t landCells = 0;      ///< Land cells of the raster.
};

/// Upstream area (km²) from which a D8 cell counts as a channel in the figures below.
inline constexpr double kChannelAreaKm2 = 1.0;

/// Slope–area fit: channel cells (area ≥ 1 km²) whose D8 path goes 4 steps downstream on
/// land; slope = (height − height 4 steps down) / path length on the raster heights; log10(A)
/// binned in 0.2-wide bins (x = bin centre), bins with ≥ 30 cells of positive slope kept,
/// y = log10 of their median slope (non-positive slopes left out).
SlopeAreaFit fitSlopeArea(const HeightRaster& raster, const FlowField& flow);

/// Slope percentiles of the land cells whose 4 neighbours are land (central differences).
SlopeStatistics measureSlopes(const HeightRaster& raster);

/// Confluences of the D8 network of channels with upstream area ≥ minAreaKm2.
ConfluenceCount countConfluences(const FlowField& flow, double minAreaKm2 = kChannelAreaKm2);

/// Drainage density: total D8 step length (km) of cells with area ≥ minAreaKm2 over the land
/// area (km²); an outlet's step counts one cell size. NaN without land.
double drainageDensity(const FlowField& flow, double minAreaKm2);

/// Dissection: median slope (tangent, central differences) over the mean slope of the heights
/// smoothed by a Gaussian of σ = 1 km (separable, truncated at 3σ, normalised over land cells),
/// both over land cells farther than 2 km from any non-land cell and the raster's edge. NaN
/// when there is no such cell.
double measureDissection(const HeightRaster& raster);

/// All of the above; `flow` must be computeFlowField(raster).
ReliefFigures measureRelief(const HeightRaster& raster, const FlowField& flow);

/// All of the above, computing the flow.
ReliefFigures measureRelief(const HeightRaster& raster);

} // namespace strahler::quality
