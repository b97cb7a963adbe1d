#pragma once

#include "strahler/quality/drainage.h"
#include "strahler/quality/horton.h"
#include "strahler/quality/river_profile.h"

#include <string>

namespace strahler::quality {

/// The three checks as one JSON object, keys always present and in this order (NaN and
/// infinities become null; lengths and heights in metres, areas in km²):
///   {"drainage": {"landCells", "drainingCells", "drainingFraction", "pits",
///                 "largestUndrainedAreaKm2", "fillToleranceM"},
///    "horton": {"streamCount": {"1": N_1, "2": N_2, ...},
///               "meanStreamLengthM": {"1": L_1, ...}, "bifurcationRatio", "lengthRatio"},
///    "rivers": {"samples", "violations", "worstRiseM", "worstAt": [x, y]}}
/// Orders run from 1 to the highest order, in numeric order. Pretty-printed, 2-space indent.
std::string analysisReportJson(const DrainageReport& drainage, const HortonStatistics& horton,
                               const RiverProfileReport& rivers);

} // namespace strahler::quality
