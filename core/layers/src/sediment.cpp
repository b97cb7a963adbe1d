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
  return perPixel(grid, [&](int x, int y) {
    return sedimentOf(tanSlope(gradientAt(grid, x, y)), concavityAt(grid, x, y));
  });
}

} // namespace strahler::layers
