#include "strahler/layers/sediment.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::layers {

double sedimentOf(double tanSlope, double concavity) noexcept {
  static const double tanRepose = std::tan(Sediment::kReposeDeg * std::numbers::pi / 180.0);
  const double stable = std::max(0.0, 1.0 - tanSlope / tanRepose);
  const double hollow = std::clamp(0.5 + concavity / (2.0 * Sediment::kConcavityScale), 0.0, 1.0);
  return Sediment::kMaxM * stable * hollow;
}

std::vector<double> sedimentThickness(const BorderedHeights& grid) {
  grid.check();
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height));
  for (int y = 0; y < grid.height; ++y)
    for (int x = 0; x < grid.width; ++x) {
      const Gradient g = gradientAt(grid, x, y);
      out.push_back(
          sedimentOf(std::sqrt(g.dzdx * g.dzdx + g.dzdy * g.dzdy), concavityAt(grid, x, y)));
    }
  return out;
}

} // namespace strahler::layers
