#include "strahler/layers/sky_view.h"

#include "upsample.h"

#include "strahler/base/assert.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace strahler::layers {
namespace {

constexpr std::size_t kStepCount = std::size(SkyView::kSteps);

/// One ray: the offsets (in samples) of its steps and their distances in spacings.
struct Ray {
  std::array<int, kStepCount> dx{}, dy{};
  std::array<double, kStepCount> distance{};
};

std::array<Ray, SkyView::kRays> makeRays() {
  std::array<Ray, SkyView::kRays> rays{};
  for (int i = 0; i < SkyView::kRays; ++i) {
    const double theta = 2.0 * std::numbers::pi * i / SkyView::kRays;
    const double east = std::sin(theta), north = std::cos(theta);
    Ray& ray = rays[static_cast<std::size_t>(i)];
    for (std::size_t k = 0; k < kStepCount; ++k) {
      const double s = SkyView::kSteps[k];
      ray.dx[k] = static_cast<int>(std::lround(s * east));
      ray.dy[k] = static_cast<int>(std::lround(-s * north)); // rows run south
      ray.distance[k] = std::hypot(ray.dx[k], ray.dy[k]);
    }
  }
  return rays;
}

/// The sky-view factor at pixels (x0 + step·i, y) for i < count.
void skyRow(const BorderedHeights& grid, int y, int x0, int step, std::size_t count, double* out) {
  static const std::array<Ray, SkyView::kRays> rays = makeRays();
  thread_local std::vector<double> steepest, sum;
  steepest.assign(count, 0.0);
  sum.assign(count, 0.0);
  const double spacing = grid.spacing(y);
  const auto stride = static_cast<std::ptrdiff_t>(grid.stride());
  const double* here = &grid.heights[static_cast<std::size_t>(y + grid.border) * grid.stride() +
                                     static_cast<std::size_t>(x0 + grid.border)];
  for (const Ray& ray : rays) {
    std::fill(steepest.begin(), steepest.end(), 0.0); // tan of the horizon; 0: clear
    for (std::size_t k = 0; k < kStepCount; ++k) {
      const double inverse = 1.0 / (ray.distance[k] * spacing);
      const double* there = here + ray.dy[k] * stride + ray.dx[k];
      for (std::size_t i = 0; i < count; ++i) {
        const auto x = static_cast<std::ptrdiff_t>(i) * step;
        steepest[i] = std::max(steepest[i], (there[x] - here[x]) * inverse);
      }
    }
    for (std::size_t i = 0; i < count; ++i) // sin(atan(t))
      sum[i] += steepest[i] / std::sqrt(1.0 + steepest[i] * steepest[i]);
  }
  for (std::size_t i = 0; i < count; ++i)
    out[i] = 1.0 - sum[i] / SkyView::kRays;
}

} // namespace

std::vector<double> skyView(const BorderedHeights& grid, int step) {
  grid.check();
  STRAHLER_ASSERT(step == 1 || (step == 2 && grid.width % 2 == 0 && grid.height % 2 == 0),
                  "skyView: step 1, or 2 on an even raster");
  STRAHLER_ASSERT(grid.border >= SkyView::kReach + step - 1,
                  "skyView: the border is shorter than a ray");
  const auto width = static_cast<std::size_t>(grid.width);
  std::vector<double> out(width * static_cast<std::size_t>(grid.height));
  if (step == 1) {
    for (int y = 0; y < grid.height; ++y)
      skyRow(grid, y, 0, 1, width, &out[static_cast<std::size_t>(y) * width]);
    return out;
  }
  // Every other pixel of every other row, the last in the border (the next tile's first),
  // then bilinear between them: the same global samples whichever tile asks.
  const std::size_t cw = width / 2 + 1, ch = static_cast<std::size_t>(grid.height) / 2 + 1;
  std::vector<double> coarse(cw * ch);
  for (std::size_t j = 0; j < ch; ++j)
    skyRow(grid, static_cast<int>(2 * j), 0, 2, cw, &coarse[j * cw]);
  return detail::upsampleEven(coarse, width, static_cast<std::size_t>(grid.height));
}

} // namespace strahler::layers
