#include "strahler/quality/relief_windows.h"

#include "d8_grid.h"

#include "strahler/quality/spectral_slope.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <tuple>

namespace strahler::quality {
namespace {

/// Index of the cell `row` rows from the north and `col` from the west.
std::size_t northIndex(const HeightRaster& r, int row, int col) {
  return std::size_t(r.height - 1 - row) * std::size_t(r.width) + std::size_t(col);
}

/// The relief of the window at (row, col), or a negative value when a cell is not land.
double windowRelief(const HeightRaster& r, int row, int col, int cells) {
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (int y = row; y < row + cells; ++y) {
    const std::size_t first = northIndex(r, y, col);
    for (std::size_t i = first; i < first + std::size_t(cells); ++i) {
      if (!d8::isLand(r, i))
        return -1.0;
      lo = std::min(lo, r.heights[i]);
      hi = std::max(hi, r.heights[i]);
    }
  }
  return double(hi) - double(lo);
}

/// One axis of scipy.ndimage.zoom: for each output index, the two input indices, the weight of
/// the second, and the nearest input index.
struct AxisSample {
  std::size_t lo, hi;
  double t;
  std::size_t nearest;
};

std::vector<AxisSample> zoomAxis(int in, int out) {
  std::vector<AxisSample> samples(static_cast<std::size_t>(out));
  const double scale = out > 1 ? double(in - 1) / double(out - 1) : 0.0;
  const std::size_t last = std::size_t(in - 1);
  for (std::size_t j = 0; j < samples.size(); ++j) {
    const double at = std::min(double(j) * scale, double(last));
    const std::size_t lo = std::min(std::size_t(at), last);
    samples[j] = {lo, std::min(lo + 1, last), at - double(lo),
                  std::min(std::size_t(std::floor(at + 0.5)), last)};
  }
  return samples;
}

} // namespace

HeightRaster resampleRaster(const HeightRaster& raster, double cellSize) {
  const double zoom = raster.cellSize / cellSize;
  HeightRaster r;
  r.width = std::max(1, int(std::nearbyint(raster.width * zoom)));
  r.height = std::max(1, int(std::nearbyint(raster.height * zoom)));
  r.cellSize = cellSize;
  r.origin = raster.origin;
  const std::vector<AxisSample> xs = zoomAxis(raster.width, r.width);
  const std::vector<AxisSample> ys = zoomAxis(raster.height, r.height);
  const std::size_t w = std::size_t(raster.width);
  r.heights.resize(std::size_t(r.width) * std::size_t(r.height));
  r.cellClass.resize(r.heights.size());
  std::size_t i = 0;
  for (const AxisSample& y : ys)
    for (const AxisSample& x : xs) {
      const auto at = [&](std::size_t yy, std::size_t xx) { return yy * w + xx; };
      const double top =
          (1 - x.t) * raster.heights[at(y.lo, x.lo)] + x.t * raster.heights[at(y.lo, x.hi)];
      const double bottom =
          (1 - x.t) * raster.heights[at(y.hi, x.lo)] + x.t * raster.heights[at(y.hi, x.hi)];
      r.heights[i] = float((1 - y.t) * top + y.t * bottom);
      bool land = d8::isLand(raster, at(y.nearest, x.nearest));
      for (std::size_t yy : {y.lo, y.hi})
        for (std::size_t xx : {x.lo, x.hi}) {
          const bool weighted =
              (yy == y.lo ? 1 - y.t : y.t) > 0 && (xx == x.lo ? 1 - x.t : x.t) > 0;
          land = land && (!weighted || d8::isLand(raster, at(yy, xx)));
        }
      r.cellClass[i++] =
          land ? raster.cellClass[at(y.nearest, x.nearest)] : std::uint8_t(CellClass::kSea);
    }
  return r;
}

std::vector<WindowPlacement> selectReliefWindows(const HeightRaster& raster, int cells, int count) {
  std::vector<WindowPlacement> candidates;
  if (cells <= 0 || count <= 0)
    return {};
  const int step = std::max(4, cells / 8);
  for (int row = 0; row + cells <= raster.height; row += step)
    for (int col = 0; col + cells <= raster.width; col += step)
      if (const double relief = windowRelief(raster, row, col, cells); relief >= 0.0)
        candidates.push_back({row, col, relief});
  std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
    return std::tie(a.reliefM, a.row, a.col) > std::tie(b.reliefM, b.row, b.col);
  });
  std::vector<WindowPlacement> kept;
  for (const WindowPlacement& c : candidates) {
    const bool apart = std::all_of(kept.begin(), kept.end(), [&](const WindowPlacement& k) {
      return std::abs(c.row - k.row) >= cells || std::abs(c.col - k.col) >= cells;
    });
    if (!apart)
      continue;
    kept.push_back(c);
    if (int(kept.size()) == count)
      break;
  }
  return kept;
}

std::vector<double> windowHeights(const HeightRaster& raster, const WindowPlacement& placement,
                                  int cells) {
  std::vector<double> heights;
  heights.reserve(std::size_t(cells) * std::size_t(cells));
  for (int y = placement.row; y < placement.row + cells; ++y) {
    const std::size_t first = northIndex(raster, y, placement.col);
    for (std::size_t i = first; i < first + std::size_t(cells); ++i)
      heights.push_back(double(raster.heights[i]));
  }
  return heights;
}

ReliefWindows measureReliefWindows(const HeightRaster& raster, double sizeKm, int count,
                                   const GeomorphonParams& params) {
  ReliefWindows out;
  out.cells = int(std::nearbyint(sizeKm * 1000.0 / raster.cellSize)); // half to even, as Python
  out.cellSize = raster.cellSize;
  std::vector<double> slopes;
  for (const WindowPlacement& p : selectReliefWindows(raster, out.cells, count)) {
    const std::vector<double> z = windowHeights(raster, p, out.cells);
    ReliefWindow window{p, spectralSlope(z, out.cells, out.cells, raster.cellSize),
                        windowGeomorphonShares(z, out.cells, out.cells, raster.cellSize, params)};
    if (!std::isnan(window.spectralSlope))
      slopes.push_back(window.spectralSlope);
    out.list.push_back(window);
  }
  if (!out.list.empty())
    for (std::size_t c = 0; c < kGeomorphonCount; ++c) {
      double sum = 0.0;
      for (const ReliefWindow& w : out.list)
        sum += w.geomorphons[c];
      out.meanGeomorphons[c] = sum / double(out.list.size());
    }
  if (!slopes.empty()) {
    // numpy.median: the middle value, or the mean of the two middle values.
    std::sort(slopes.begin(), slopes.end());
    const std::size_t n = slopes.size();
    out.medianSpectralSlope =
        n % 2 == 1 ? slopes[n / 2] : 0.5 * (slopes[n / 2 - 1] + slopes[n / 2]);
  }
  return out;
}

WindowComparison compareReliefWindows(const ReliefWindows& windows, const std::string& dem,
                                      double demCellSize, const ReliefWindows& demWindows) {
  WindowComparison c;
  c.dem = dem;
  c.demCellSize = demCellSize;
  c.demWindows = demWindows;
  c.geomorphonDistance = geomorphonDistance(windows.meanGeomorphons, demWindows.meanGeomorphons);
  c.spectralSlopeDifference = windows.medianSpectralSlope - demWindows.medianSpectralSlope;
  return c;
}

} // namespace strahler::quality
