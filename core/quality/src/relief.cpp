#include "strahler/quality/relief.h"

#include "d8_grid.h"
#include "line_fit.h"

#include "strahler/base/assert.h"
#include "strahler/geometry/distance_transform.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

namespace strahler::quality {
namespace {

using d8::Cell;
using d8::isLand;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRadToDeg = 57.29577951308232;
constexpr int kSlopeSteps = 4;      // slope–area: cells downstream
constexpr double kBinWidth = 0.2;   // slope–area: log10(A) bin width
constexpr std::size_t kMinBin = 30; // slope–area: cells per kept bin
constexpr double kSmoothingSigmaM = 1000.0;
constexpr double kInteriorM = 2000.0;

/// The p-quantile (0..1) of `values` with linear interpolation between ranks; reorders them.
double quantile(std::vector<double>& values, double p) {
  if (values.empty())
    return kNaN;
  const double pos = p * double(values.size() - 1);
  const std::size_t lo = std::size_t(pos);
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(lo), values.end());
  const double a = values[lo];
  if (lo + 1 >= values.size())
    return a;
  const double b = *std::min_element(values.begin() + std::ptrdiff_t(lo) + 1, values.end());
  return a + (b - a) * (pos - double(lo));
}

/// Central-difference gradient magnitude (tangent of the slope) of `z` at (x, y); the four
/// neighbours must exist.
double gradientAt(const std::vector<float>& z, int width, double cellSize, int x, int y) {
  const std::size_t w = std::size_t(width), i = std::size_t(y) * w + std::size_t(x);
  const double gx = (double(z[i + 1]) - double(z[i - 1])) / (2.0 * cellSize);
  const double gy = (double(z[i + w]) - double(z[i - w])) / (2.0 * cellSize);
  return std::sqrt(gx * gx + gy * gy);
}

/// True when (x, y) and its four neighbours are land cells of the raster.
bool hasLandCross(const HeightRaster& r, int x, int y) {
  if (x <= 0 || y <= 0 || x >= r.width - 1 || y >= r.height - 1)
    return false;
  const std::size_t w = std::size_t(r.width), i = std::size_t(y) * w + std::size_t(x);
  return isLand(r, i) && isLand(r, i - 1) && isLand(r, i + 1) && isLand(r, i - w) &&
         isLand(r, i + w);
}

/// One pass of a 1-D kernel along x (step 1) or y (step width) over `in`, into `out`.
void convolveAxis(const std::vector<float>& in, std::vector<float>& out, int width, int height,
                  const std::vector<float>& kernel, bool alongY) {
  const int radius = int(kernel.size() / 2);
  const std::size_t w = std::size_t(width);
  std::fill(out.begin(), out.end(), 0.0f);
  if (alongY) {
    for (int y = 0; y < height; ++y)
      for (int k = -radius; k <= radius; ++k) {
        const int sy = y + k;
        if (sy < 0 || sy >= height)
          continue;
        const float wk = kernel[std::size_t(k + radius)];
        const float* src = &in[std::size_t(sy) * w];
        float* dst = &out[std::size_t(y) * w];
        for (std::size_t x = 0; x < w; ++x)
          dst[x] += wk * src[x];
      }
    return;
  }
  for (int y = 0; y < height; ++y) {
    const float* src = &in[std::size_t(y) * w];
    float* dst = &out[std::size_t(y) * w];
    for (int x = 0; x < width; ++x) {
      const int lo = std::max(-radius, -x), hi = std::min(radius, width - 1 - x);
      float sum = 0.0f;
      for (int k = lo; k <= hi; ++k)
        sum += kernel[std::size_t(k + radius)] * src[x + k];
      dst[x] = sum;
    }
  }
}

/// Heights smoothed by a Gaussian of σ metres, normalised over land cells (water and
/// outside cells neither contribute nor receive a meaningful value).
std::vector<float> smoothOverLand(const HeightRaster& r, double sigma) {
  const double sigmaCells = sigma / r.cellSize;
  const int radius = std::max(1, int(std::ceil(3.0 * sigmaCells)));
  std::vector<float> kernel(std::size_t(2 * radius + 1));
  for (int k = -radius; k <= radius; ++k)
    kernel[std::size_t(k + radius)] = float(std::exp(-0.5 * k * k / (sigmaCells * sigmaCells)));
  const std::size_t n = r.heights.size();
  std::vector<float> weighted(n), mask(n), tmp(n);
  for (std::size_t i = 0; i < n; ++i) {
    mask[i] = isLand(r, i) ? 1.0f : 0.0f;
    weighted[i] = mask[i] * r.heights[i];
  }
  for (std::vector<float>* field : {&weighted, &mask}) {
    convolveAxis(*field, tmp, r.width, r.height, kernel, false);
    convolveAxis(tmp, *field, r.width, r.height, kernel, true);
  }
  for (std::size_t i = 0; i < n; ++i)
    weighted[i] = mask[i] > 0.0f ? weighted[i] / mask[i] : 0.0f;
  return weighted;
}

/// Land cells farther than `margin` metres from every non-land cell and the raster's edge.
std::vector<Cell> interiorCells(const HeightRaster& r, double margin) {
  std::vector<std::uint8_t> water(r.heights.size());
  for (std::size_t i = 0; i < water.size(); ++i)
    water[i] = isLand(r, i) ? 0 : 1;
  const std::vector<float> toWater =
      geometry::distanceToMarked(r.width, r.height, r.cellSize, water);
  std::vector<Cell> cells;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const int edge = std::min(std::min(x, r.width - 1 - x), std::min(y, r.height - 1 - y));
      const std::size_t i = std::size_t(y) * std::size_t(r.width) + std::size_t(x);
      if ((double(edge) + 0.5) * r.cellSize > margin && toWater[i] > margin && isLand(r, i))
        cells.push_back(Cell(i));
    }
  return cells;
}

} // namespace

SlopeAreaFit fitSlopeArea(const HeightRaster& raster, const FlowField& flow) {
  std::map<long, std::vector<double>> bins;
  for (Cell c : flow.order) {
    if (flow.areaKm2[c] < kChannelAreaKm2)
      continue;
    Cell at = c;
    double length = 0.0;
    for (int s = 0; s < kSlopeSteps && at != FlowField::kNone; ++s) {
      const Cell next = flow.receiver[at];
      if (next != FlowField::kNone)
        length += stepLength(flow, at, next);
      at = next;
    }
    if (at == FlowField::kNone)
      continue; // the path leaves the land within 4 steps
    const double slope = (double(raster.heights[c]) - double(raster.heights[at])) / length;
    if (slope > 0.0)
      bins[long(std::floor(std::log10(flow.areaKm2[c]) / kBinWidth))].push_back(slope);
  }
  std::vector<double> logArea, logSlope;
  for (auto& [bin, slopes] : bins)
    if (slopes.size() >= kMinBin) {
      logArea.push_back((double(bin) + 0.5) * kBinWidth);
      logSlope.push_back(std::log10(quantile(slopes, 0.5)));
    }
  const detail::LineFit line = detail::fitLine(logArea, logSlope);
  return {-line.slope, line.r2, logArea.size()};
}

SlopeStatistics measureSlopes(const HeightRaster& raster) {
  std::vector<double> degrees;
  std::size_t steep = 0;
  for (int y = 1; y + 1 < raster.height; ++y)
    for (int x = 1; x + 1 < raster.width; ++x) {
      if (!hasLandCross(raster, x, y))
        continue;
      const double deg =
          std::atan(gradientAt(raster.heights, raster.width, raster.cellSize, x, y)) * kRadToDeg;
      degrees.push_back(deg);
      steep += deg > 45.0 ? 1 : 0;
    }
  SlopeStatistics stats;
  stats.cells = degrees.size();
  stats.steeperThan45 = degrees.empty() ? kNaN : double(steep) / double(degrees.size());
  stats.p50Deg = quantile(degrees, 0.5);
  stats.p90Deg = quantile(degrees, 0.9);
  stats.p99Deg = quantile(degrees, 0.99);
  return stats;
}

ConfluenceCount countConfluences(const FlowField& flow, double minAreaKm2) {
  std::vector<std::uint8_t> inflows(flow.areaKm2.size(), 0);
  for (Cell c : flow.order) {
    const Cell r = flow.receiver[c];
    if (flow.areaKm2[c] >= minAreaKm2 && r != FlowField::kNone && inflows[r] < 8)
      ++inflows[r];
  }
  ConfluenceCount count;
  for (Cell c : flow.order) {
    if (flow.areaKm2[c] < minAreaKm2 || inflows[c] < 2)
      continue;
    ++count.confluences;
    count.threeOrMore += inflows[c] >= 3 ? 1 : 0;
  }
  count.shareThreeOrMore =
      count.confluences == 0 ? kNaN : double(count.threeOrMore) / double(count.confluences);
  return count;
}

double drainageDensity(const FlowField& flow, double minAreaKm2) {
  double lengthM = 0.0;
  for (Cell c : flow.order)
    if (flow.areaKm2[c] >= minAreaKm2)
      lengthM += stepLength(flow, c, flow.receiver[c]);
  const double landKm2 = double(flow.order.size()) * flow.cellSize * flow.cellSize * 1e-6;
  return landKm2 > 0 ? lengthM * 1e-3 / landKm2 : kNaN;
}

double measureDissection(const HeightRaster& raster) {
  const std::vector<Cell> cells = interiorCells(raster, kInteriorM);
  if (cells.empty())
    return kNaN;
  const std::vector<float> smooth = smoothOverLand(raster, kSmoothingSigmaM);
  std::vector<double> slopes;
  slopes.reserve(cells.size());
  double smoothSum = 0.0;
  for (Cell c : cells) {
    const int x = int(c % Cell(raster.width)), y = int(c / Cell(raster.width));
    slopes.push_back(gradientAt(raster.heights, raster.width, raster.cellSize, x, y));
    smoothSum += gradientAt(smooth, raster.width, raster.cellSize, x, y);
  }
  const double smoothMean = smoothSum / double(cells.size());
  return smoothMean > 0 ? quantile(slopes, 0.5) / smoothMean : kNaN;
}

ReliefFigures measureRelief(const HeightRaster& raster) {
  return measureRelief(raster, computeFlowField(raster));
}

ReliefFigures measureRelief(const HeightRaster& raster, const FlowField& flow) {
  ReliefFigures figures;
  figures.landCells = flow.order.size();
  figures.slopeArea = fitSlopeArea(raster, flow);
  figures.slopes = measureSlopes(raster);
  figures.confluences = countConfluences(flow, kChannelAreaKm2);
  figures.drainageDensity01 = drainageDensity(flow, 0.1);
  figures.drainageDensity1 = drainageDensity(flow, kChannelAreaKm2);
  figures.dissection = measureDissection(raster);
  figures.highest = kNaN;
  for (std::size_t i = 0; i < raster.heights.size(); ++i)
    if (isLand(raster, i))
      figures.highest = std::isnan(figures.highest)
                            ? double(raster.heights[i])
                            : std::max(figures.highest, double(raster.heights[i]));
  return figures;
}

} // namespace strahler::quality
