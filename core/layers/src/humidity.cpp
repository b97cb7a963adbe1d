#include "strahler/layers/humidity.h"

#include "upsample.h"

#include "strahler/base/assert.h"
#include "strahler/tiling/river_segments.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::layers {

namespace {

/// The rivers' wetness at every sample inside a border of `border` samples, row-major.
std::vector<double> wetnessAt(const construction::World& world, const tiling::SampleGrid& grid,
                              int border) {
  // The least distance-to-reach ratio per sample (exp is monotonic: one exp per sample).
  constexpr double kBeyond = 3.0;
  const auto b = static_cast<std::size_t>(border);
  const auto width = static_cast<std::size_t>(grid.width);
  const std::size_t insideWidth = width - 2 * b,
                    insideHeight = static_cast<std::size_t>(grid.height) - 2 * b;
  std::vector<double> ratio(insideWidth * insideHeight, kBeyond);
  // A river counts at a sample when its wetness reaches half the row spacing (3R ≥ s / 2):
  // R ≥ s / 6 needs a width ≥ (s / 6 − base) / per.
  const auto widthFor = [](double spacing) {
    return std::max(0.0, (spacing / 6.0 - Humidity::kReachBaseM) / Humidity::kReachPerWidth);
  };
  const double minWidth =
      widthFor(*std::min_element(grid.rowSpacing.begin(), grid.rowSpacing.end()));
  std::vector<double> rowWidth(grid.rowSpacing.size());
  std::transform(grid.rowSpacing.begin(), grid.rowSpacing.end(), rowWidth.begin(), widthFor);
  const tiling::GridRows rows(grid);
  tiling::forEachRiverSegment(
      world, grid.bounds, minWidth, kBeyond * Humidity::kMaxReachM,
      [&](const tiling::RiverSegment& segment) {
        const double half = segment.halfWidth;
        const double reach = std::min(
            Humidity::kMaxReachM, Humidity::kReachBaseM + Humidity::kReachPerWidth * 2.0 * half);
        geometry::Aabb box;
        box.add(segment.a);
        box.add(segment.b);
        const double far = half + kBeyond * reach;
        rows.forEachIn(box.expanded(far), [&](std::size_t j, std::size_t i) {
          if (j < b || i < b || j - b >= insideHeight || i - b >= insideWidth)
            return;
          double& r = ratio[(j - b) * insideWidth + (i - b)];
          if (r == 0.0 || 2.0 * half < rowWidth[j]) // in a channel already; or too narrow
            return;
          const double d2 =
              tiling::distance2ToSegment(grid.points[j * width + i], segment.a, segment.b);
          if (d2 >= far * far)
            return;
          r = std::min(r, std::max(0.0, std::sqrt(d2) - half) / reach);
        });
      });
  // exp(−d/R) lowered to reach 0 at 3R (no step where the reach ends), 1 in the channel.
  const double floor = std::exp(-kBeyond);
  std::vector<double> wet(ratio.size(), 0.0);
  for (std::size_t k = 0; k < ratio.size(); ++k)
    if (ratio[k] < kBeyond)
      wet[k] = (std::exp(-ratio[k]) - floor) / (1.0 - floor);
  return wet;
}

} // namespace

tiling::SampleGrid samplesInside(const tiling::SampleGrid& grid, int border, int step) {
  const auto b = static_cast<std::size_t>(border), width = static_cast<std::size_t>(grid.width);
  const int insideWidth = grid.width - 2 * border, insideHeight = grid.height - 2 * border;
  STRAHLER_ASSERT(step == 1 ||
                      (step == 2 && border >= 1 && insideWidth % 2 == 0 && insideHeight % 2 == 0),
                  "samplesInside: step 1, or 2 on an even raster with a border");
  tiling::SampleGrid out;
  out.width = step == 1 ? insideWidth : insideWidth / 2 + 1;
  out.height = step == 1 ? insideHeight : insideHeight / 2 + 1;
  const auto s = static_cast<std::size_t>(step);
  out.points.reserve(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height));
  for (std::size_t j = 0; j < static_cast<std::size_t>(out.height); ++j) {
    const std::size_t row = b + s * j;
    out.rowSpacing.push_back(grid.rowSpacing[row]);
    for (std::size_t i = 0; i < static_cast<std::size_t>(out.width); ++i) {
      out.points.push_back(grid.points[row * width + b + s * i]);
      out.bounds.add(out.points.back());
    }
  }
  return out;
}

std::vector<double> riverWetness(const construction::World& world, const tiling::SampleGrid& grid,
                                 int border, int step) {
  if (step == 1)
    return wetnessAt(world, grid, border);
  STRAHLER_ASSERT(step == 2, "riverWetness: step 1 or 2");
  return detail::upsampleEven(riverWetnessEven(world, grid, border),
                              static_cast<std::size_t>(grid.width - 2 * border),
                              static_cast<std::size_t>(grid.height - 2 * border));
}

std::vector<double> riverWetnessEven(const construction::World& world,
                                     const tiling::SampleGrid& grid, int border) {
  // Every sample of the even samples' own grid: the same values as every other sample of the
  // bordered grid (a sample's wetness is its own; the rivers left out by the smaller box and
  // the coarser rows' spacing reach none of them), without visiting the others.
  return wetnessAt(world, samplesInside(grid, border, 2), 0);
}

double localWetness(double tanSlope, double concavity) noexcept {
  static const double tanDry = std::tan(Humidity::kDrySlopeDeg * std::numbers::pi / 180.0);
  const double flat = std::max(0.0, 1.0 - tanSlope / tanDry);
  const double hollow = std::clamp(0.5 + concavity / (2.0 * Humidity::kConcavityScale), 0.0, 1.0);
  return Humidity::kLocalWeight * flat * hollow;
}

std::vector<double> humidity(const BorderedHeights& grid, std::span<const double> wetness) {
  grid.check();
  STRAHLER_ASSERT(wetness.size() ==
                      static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height),
                  "humidity: one wetness per pixel");
  return perPixel(grid, [&](int x, int y) {
    if (grid.at(x, y) < 0.0)
      return 1.0;
    const double river =
        wetness[static_cast<std::size_t>(y) * static_cast<std::size_t>(grid.width) +
                static_cast<std::size_t>(x)];
    return std::max(river, localWetness(tanSlope(gradientAt(grid, x, y)), concavityAt(grid, x, y)));
  });
}

} // namespace strahler::layers
