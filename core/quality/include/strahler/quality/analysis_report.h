#pragma once

#include "strahler/quality/drainage.h"
#include "strahler/quality/geomorphons.h"
#include "strahler/quality/hack_law.h"
#include "strahler/quality/horton.h"
#include "strahler/quality/network_coverage.h"
#include "strahler/quality/relief.h"
#include "strahler/quality/relief_windows.h"
#include "strahler/quality/river_agreement.h"
#include "strahler/quality/river_profile.h"

#include <limits>
#include <optional>
#include <string>

namespace strahler::quality {

/// The relief section of a report: figures of the terrain as it is (no rivers burnt in).
struct ReliefReport {
  int width = 0;                ///< Raster cells per row.
  int height = 0;               ///< Raster rows.
  double cellSize = 0.0;        ///< Raster cell side, metres.
  ReliefFigures terrain;        ///< Figures of the heights alone.
  NetworkReliefFigures network; ///< Figures against the world's rivers (NaN for a DEM).
  /// checkDrainage's drainingFraction on the unburnt raster; NaN when not measured.
  double drainingFractionUnburnt = std::numeric_limits<double>::quiet_NaN();
  GeomorphonParams geomorphonParams; ///< Parameters of the two geomorphon figures.
  /// geomorphonShares over every land cell; NaN when not measured.
  GeomorphonShares geomorphons = noGeomorphonShares();
  double windowKm = kReliefWindowKm; ///< Side of the relief windows, km.
  ReliefWindows windows;             ///< measureReliefWindows of the raster.
  /// With `analyze WORLD --compare-dem FILE`: the windows against that DEM's.
  std::optional<WindowComparison> comparison;
};

/// The checks as one JSON object, keys always present and in this order (NaN and
/// infinities become null; lengths and heights in metres, areas in km²):
///   {"drainage": {"landCells", "drainingCells", "drainingFraction", "drainingFractionUnburnt",
///                 "pits", "largestUndrainedAreaKm2", "largestUndrainedAt" (local x, y of
///                 its lowest cell, when there is one), "fillToleranceM"},
///    "horton": {"streamCount": {"1": N_1, "2": N_2, ...},
///               "meanStreamLengthM": {"1": L_1, ...}, "bifurcationRatio", "lengthRatio",
///               "fractalDimension" (ln Rb / ln Rl, seed 001)},
///    "hack": {"definition", "nodes": fit, "outlets": fit} with fit = {"exponent",
///             "coefficient", "r2", "points"} (hack_law.h; L in km, A in km²),
///    "coverage": {"definition", "farthestFromRiverM", "farthestAt": [x, y] or null,
///                 "fartherThan3KmFraction", "cellSizeM"} (network_coverage.h),
///    "rivers": {"samples", "violations", "worstRiseM", "worstAt": [x, y]},
///    "relief": see reliefJson below}
/// Orders run from 1 to the highest order, in numeric order. Pretty-printed, 2-space indent.
std::string analysisReportJson(const DrainageReport& drainage, const HortonStatistics& horton,
                               const RiverProfileReport& rivers, const ReliefReport& relief,
                               const HackLaw& hack = {}, const NetworkCoverage& coverage = {});

/// `{"dem": path, "relief": {...}}` for `strahler analyze --dem`, with the relief object:
///   {"raster": {"width", "height", "cellSizeM", "landCells"},
///    "slopeArea": {"theta", "r2", "bins"}, "slopeDeg": {"p50", "p90", "p99"},
///    "steeperThan45Fraction", "confluences", "confluences3PlusFraction",
///    "drainageDensityKmPerKm2": {"0.1": ≥ 0.1 km² channels, "1": ≥ 1 km² channels},
///    "dissection", "highestM", "channelsNearRiversFraction", "riversNearChannelsFraction",
///    "networkConfluences3PlusFraction",
///    "riverDistanceM": {"p99", "max", "fartherThan3KmFraction", "farthestAt": [x, y]},
///    "sinuosity": {"B", "E", "D", "D-delta"},
///    "geomorphons": {"lookupM", "flatDeg", "shares": {"flat", "peak", ..., "pit"}},
///    "windows": {"sizeKm", "cellSizeM", "cells", "meanGeomorphons": shares, "medianSpectralSlope",
///                "list": [{"row", "col", "reliefM", "spectralSlope", "geomorphons": shares}]},
///    "comparison": null, or with --compare-dem {"dem", "demCellSizeM", "demWindows" (count),
///                  "demMeanGeomorphons": shares, "demMedianSpectralSlope",
///                  "geomorphonDistance", "spectralSlopeDifference"}}
/// (definitions in relief.h, river_agreement.h, geomorphons.h, spectral_slope.h and
/// relief_windows.h; the network figures are null without a world; "windows" rows count from
/// the north edge, as blind_set.py's).
std::string demReportJson(const std::string& path, const ReliefReport& relief);

} // namespace strahler::quality
