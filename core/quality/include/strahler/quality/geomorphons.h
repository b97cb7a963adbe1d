#pragma once

#include "strahler/quality/drainage.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace strahler::quality {

/// The ten geomorphon classes (Jasiewicz & Stepinski 2013), in r.geomorphon's order.
enum class Geomorphon : std::uint8_t {
  kFlat,
  kPeak,
  kRidge,
  kShoulder,
  kSpur,
  kSlope,
  kHollow,
  kFootslope,
  kValley,
  kPit,
};

/// Number of geomorphon classes.
inline constexpr std::size_t kGeomorphonCount = 10;

/// Lower-case names of the classes, indexed by Geomorphon ("flat", "peak", ..., "pit").
extern const std::array<const char*, kGeomorphonCount> kGeomorphonNames;

/// Share of each class (indexed by Geomorphon), summing to 1; all NaN without cells.
using GeomorphonShares = std::array<double, kGeomorphonCount>;

/// Shares that are all NaN (nothing measured).
constexpr GeomorphonShares noGeomorphonShares() {
  GeomorphonShares shares{};
  for (double& s : shares)
    s = std::numeric_limits<double>::quiet_NaN();
  return shares;
}

/// The two parameters of the classification.
struct GeomorphonParams {
  double lookupM = 360.0; ///< Lookup distance, metres: L = max(2, round(lookupM / cell)) cells.
  double flatDeg = 1.0;   ///< Flatness threshold, degrees.
};

/// The lookup distance in cells for `cellSize` metres: max(2, round(lookupM / cellSize)).
int geomorphonLookupCells(const GeomorphonParams& params, double cellSize);

/// Classifies every land cell (others get kFlat and should be ignored), as blind_set.py's
/// geomorphons() does: along each of the 8 directions, the zenith angle up = max over steps
/// i = 1..L of atan((z_i − z)/(i·cell·|d|)) and down = max of −atan(…); the direction looks
/// up if up − down > flatDeg, down if down − up > flatDeg; the class is the r.geomorphon
/// table's entry for (directions down, directions up). Beyond the raster's edge the lookup sees
/// the edge cell's height (edge padding); it stops before the first non-land cell.
/// O(cells · 8 · L).
std::vector<Geomorphon> classifyGeomorphons(const HeightRaster& raster,
                                            const GeomorphonParams& params = {});

/// Class shares over every land cell of the raster (classifyGeomorphons).
GeomorphonShares geomorphonShares(const HeightRaster& raster, const GeomorphonParams& params = {});

/// blind_set.py's geomorphons() of a square (or rectangular) window of heights, north row
/// first or south row first alike (the 8 directions are symmetric): shares over the cells at
/// least L cells from the window's edge (its interior); all NaN when there is none.
GeomorphonShares windowGeomorphonShares(const std::vector<double>& heights, int width, int height,
                                        double cellSize, const GeomorphonParams& params = {});

/// Half the L1 distance between two share vectors, 0..1 (NaN if either holds a NaN).
double geomorphonDistance(const GeomorphonShares& a, const GeomorphonShares& b);

} // namespace strahler::quality
