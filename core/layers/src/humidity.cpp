#include "strahler/layers/humidity.h"

#include "upsample.h"

#include "strahler/base/assert.h"
#include "strahler/tiling/river_segments.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::layers {

std::vector<double> riverWetness(const construction::World& world, const tiling::SampleGrid& grid,
                                 int border, int step) {
  // The least distance-to-reach ratio per sample (exp is monotonic: one exp per sample).
  constexpr double kBeyond = 3.0;
  const auto b = static_cast<std::size_t>(border);
  const auto width = static_cast<std::size_t>(grid.width);
  const std::size_t insideWidth = width - 2 * b,
                    insideHeight = static_cast<std::size_t>(grid.height) - 2 * b;
  STRAHLER_ASSERT(step == 1 ||
                      (step == 2 && border >= 1 && insideWidth % 2 == 0 && insideHeight % 2 == 0),
                  "riverWetness: step 1, or 2 on an even raster with a border");
  // The samples computed: every one inside, or (step 2) every other one of every other row up
  // to the first of the border, the next tile's first.
  const auto s = static_cast<std::size_t>(step);
  const std::size_t cw = step == 1 ? insideWidth : insideWidth / 2 + 1,
                    ch = step == 1 ? insideHeight : insideHeight / 2 + 1;
  std::vector<double> ratio(cw * ch, kBeyond);
  // A river counts at a sample when its wetness reaches half the row spacing (3R ≥ s / 2):
  // R ≥ s / 6 needs a width ≥ (s / 6 − base) / per.
  const auto widthFor = [](double spacing) {
    return std::max(0.0, (spacing / 6.0 - Humidity::kReachBaseM) / Humidity::kReachPerWidth);
  };
  const double minWidth =
      widthFor(*std::min_element(grid.rowSpacing.begin(), grid.rowSpacing.end()));
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
          if (j < b || i < b || (j - b) % s != 0 || (i - b) % s != 0)
            return;
          const std::size_t cj = (j - b) / s, ci = (i - b) / s;
          if (cj >= ch || ci >= cw)
            return;
          const double d2 =
              tiling::distance2ToSegment(grid.points[j * width + i], segment.a, segment.b);
          if (d2 >= far * far || 2.0 * half < widthFor(grid.rowSpacing[j]))
            return;
          double& r = ratio[cj * cw + ci];
          r = std::min(r, std::max(0.0, std::sqrt(d2) - half) / reach);
        });
      });
  // exp(−d/R) lowered to reach 0 at 3R (no step where the reach ends), 1 in the channel.
  const double floor = std::exp(-kBeyond);
  std::vector<double> wet(ratio.size(), 0.0);
  for (std::size_t k = 0; k < ratio.size(); ++k)
    if (ratio[k] < kBeyond)
      wet[k] = (std::exp(-ratio[k]) - floor) / (1.0 - floor);
  return step == 1 ? wet : detail::upsampleEven(wet, insideWidth, insideHeight);
}

std::vector<double> humidity(const BorderedHeights& grid, std::span<const double> wetness) {
  grid.check();
  STRAHLER_ASSERT(wetness.size() ==
                      static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height),
                  "humidity: one wetness per pixel");
  const double tanDry = std::tan(Humidity::kDrySlopeDeg * std::numbers::pi / 180.0);
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height));
  for (int y = 0; y < grid.height; ++y)
    for (int x = 0; x < grid.width; ++x) {
      if (grid.at(x, y) < 0.0) {
        out.push_back(1.0);
        continue;
      }
      const Gradient g = gradientAt(grid, x, y);
      const double flat =
          std::max(0.0, 1.0 - std::sqrt(g.dzdx * g.dzdx + g.dzdy * g.dzdy) / tanDry);
      const double hollow =
          std::clamp(0.5 + concavityAt(grid, x, y) / (2.0 * Humidity::kConcavityScale), 0.0, 1.0);
      const double river =
          wetness[static_cast<std::size_t>(y) * static_cast<std::size_t>(grid.width) +
                  static_cast<std::size_t>(x)];
      out.push_back(std::max(river, Humidity::kLocalWeight * flat * hollow));
    }
  return out;
}

} // namespace strahler::layers
