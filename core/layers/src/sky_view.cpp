#include "strahler/layers/sky_view.h"

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

} // namespace

std::vector<double> skyView(const BorderedHeights& grid) {
  grid.check();
  STRAHLER_ASSERT(grid.border >= SkyView::kReach, "skyView: the border is shorter than a ray");
  static const std::array<Ray, SkyView::kRays> rays = makeRays();
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height));
  for (int y = 0; y < grid.height; ++y) {
    const double spacing = grid.spacing(y);
    for (int x = 0; x < grid.width; ++x) {
      const double h = grid.at(x, y);
      double sum = 0.0;
      for (const Ray& ray : rays) {
        double steepest = 0.0; // tan of the horizon's elevation, 0 for a clear horizon
        for (std::size_t k = 0; k < kStepCount; ++k)
          steepest = std::max(steepest, (grid.at(x + ray.dx[k], y + ray.dy[k]) - h) /
                                            (ray.distance[k] * spacing));
        sum += steepest / std::sqrt(1.0 + steepest * steepest); // sin(atan(t))
      }
      out.push_back(1.0 - sum / SkyView::kRays);
    }
  }
  return out;
}

} // namespace strahler::layers
