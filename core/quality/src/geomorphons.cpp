#include "strahler/quality/geomorphons.h"

#include "d8_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strahler::quality {

const std::array<const char*, kGeomorphonCount> kGeomorphonNames = {
    "flat", "peak", "ridge", "shoulder", "spur", "slope", "hollow", "footslope", "valley", "pit"};

namespace {

using G = Geomorphon;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegToRad = 0.017453292519943295;

/// r.geomorphon's lookup table: kTable[directions looking down][directions looking up]
/// (entries past down + up = 8 cannot occur).
constexpr G kTable[9][9] = {
    {G::kFlat, G::kFlat, G::kFlat, G::kFootslope, G::kFootslope, G::kValley, G::kValley, G::kValley,
     G::kPit},
    {G::kFlat, G::kFlat, G::kFootslope, G::kFootslope, G::kFootslope, G::kValley, G::kValley,
     G::kValley, G::kSlope},
    {G::kFlat, G::kShoulder, G::kSlope, G::kSlope, G::kHollow, G::kHollow, G::kValley, G::kSlope,
     G::kSlope},
    {G::kShoulder, G::kShoulder, G::kSlope, G::kSlope, G::kSlope, G::kHollow, G::kSlope, G::kSlope,
     G::kSlope},
    {G::kShoulder, G::kShoulder, G::kSpur, G::kSlope, G::kSlope, G::kSlope, G::kSlope, G::kSlope,
     G::kSlope},
    {G::kRidge, G::kRidge, G::kSpur, G::kSpur, G::kSlope, G::kSlope, G::kSlope, G::kSlope,
     G::kSlope},
    {G::kRidge, G::kRidge, G::kRidge, G::kSlope, G::kSlope, G::kSlope, G::kSlope, G::kSlope,
     G::kSlope},
    {G::kRidge, G::kRidge, G::kSlope, G::kSlope, G::kSlope, G::kSlope, G::kSlope, G::kSlope,
     G::kSlope},
    {G::kPeak, G::kSlope, G::kSlope, G::kSlope, G::kSlope, G::kSlope, G::kSlope, G::kSlope,
     G::kSlope},
};

/// Heights and a land mask (empty: all land) on a width × height grid.
struct Grid {
  const std::vector<double>& z;
  const std::vector<std::uint8_t>& land;
  int width;
  int height;
  double cellSize;
};

/// The class of cell (x, y) of `g` with lookup L cells and threshold `flat` radians.
G classifyCell(const Grid& g, int x, int y, int lookup, double flat) {
  const std::size_t w = std::size_t(g.width);
  const double z0 = g.z[std::size_t(y) * w + std::size_t(x)];
  int up = 0, down = 0;
  for (std::size_t k = 0; k < 8; ++k) {
    const int dx = d8::kDx[k], dy = d8::kDy[k];
    const double unit = (dx != 0 && dy != 0) ? d8::kDiagonal : 1.0;
    double highest = -std::numeric_limits<double>::infinity();
    double lowest = std::numeric_limits<double>::infinity();
    for (int i = 1; i <= lookup; ++i) {
      const int nx = std::clamp(x + dx * i, 0, g.width - 1);
      const int ny = std::clamp(y + dy * i, 0, g.height - 1);
      const std::size_t n = std::size_t(ny) * w + std::size_t(nx);
      if (!g.land.empty() && g.land[n] == 0)
        break;
      // atan is monotone, so the largest angle is the atan of the largest tangent.
      const double tangent = (g.z[n] - z0) / (g.cellSize * double(i) * unit);
      highest = std::max(highest, tangent);
      lowest = std::min(lowest, tangent);
    }
    if (highest == -std::numeric_limits<double>::infinity())
      continue; // no cell to look at: neither up nor down
    const double zenith = std::atan(highest), nadir = -std::atan(lowest);
    up += zenith - nadir > flat ? 1 : 0;
    down += nadir - zenith > flat ? 1 : 0;
  }
  return kTable[down][up];
}

GeomorphonShares sharesOf(const std::vector<std::size_t>& counts, std::size_t total) {
  GeomorphonShares shares;
  for (std::size_t c = 0; c < kGeomorphonCount; ++c)
    shares[c] = total == 0 ? kNaN : double(counts[c]) / double(total);
  return shares;
}

} // namespace

int geomorphonLookupCells(const GeomorphonParams& params, double cellSize) {
  return std::max(2, int(std::lround(params.lookupM / cellSize)));
}

std::vector<Geomorphon> classifyGeomorphons(const HeightRaster& raster,
                                            const GeomorphonParams& params) {
  const std::size_t n = raster.heights.size();
  std::vector<double> z(raster.heights.begin(), raster.heights.end());
  std::vector<std::uint8_t> land(n);
  for (std::size_t i = 0; i < n; ++i)
    land[i] = d8::isLand(raster, i) ? 1 : 0;
  const Grid grid{z, land, raster.width, raster.height, raster.cellSize};
  const int lookup = geomorphonLookupCells(params, raster.cellSize);
  const double flat = params.flatDeg * kDegToRad;
  std::vector<Geomorphon> classes(n, Geomorphon::kFlat);
  for (int y = 0; y < raster.height; ++y)
    for (int x = 0; x < raster.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(raster.width) + std::size_t(x);
      if (land[i] != 0)
        classes[i] = classifyCell(grid, x, y, lookup, flat);
    }
  return classes;
}

GeomorphonShares geomorphonShares(const HeightRaster& raster, const GeomorphonParams& params) {
  const std::vector<Geomorphon> classes = classifyGeomorphons(raster, params);
  std::vector<std::size_t> counts(kGeomorphonCount, 0);
  std::size_t total = 0;
  for (std::size_t i = 0; i < classes.size(); ++i)
    if (d8::isLand(raster, i)) {
      ++counts[std::size_t(classes[i])];
      ++total;
    }
  return sharesOf(counts, total);
}

GeomorphonShares windowGeomorphonShares(const std::vector<double>& heights, int width, int height,
                                        double cellSize, const GeomorphonParams& params) {
  static const std::vector<std::uint8_t> kAllLand;
  const Grid grid{heights, kAllLand, width, height, cellSize};
  const int lookup = geomorphonLookupCells(params, cellSize);
  const double flat = params.flatDeg * kDegToRad;
  std::vector<std::size_t> counts(kGeomorphonCount, 0);
  std::size_t total = 0;
  for (int y = lookup; y < height - lookup; ++y)
    for (int x = lookup; x < width - lookup; ++x) {
      ++counts[std::size_t(classifyCell(grid, x, y, lookup, flat))];
      ++total;
    }
  return sharesOf(counts, total);
}

double geomorphonDistance(const GeomorphonShares& a, const GeomorphonShares& b) {
  double sum = 0.0;
  for (std::size_t c = 0; c < kGeomorphonCount; ++c)
    sum += std::abs(a[c] - b[c]);
  return 0.5 * sum;
}

} // namespace strahler::quality
