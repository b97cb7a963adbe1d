#include "strahler/layers/sediment.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::layers {

std::vector<double> sedimentThickness(const BorderedHeights& grid) {
  grid.check();
  const double tanRepose = std::tan(Sediment::kReposeDeg * std::numbers::pi / 180.0);
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height));
  for (int y = 0; y < grid.height; ++y)
    for (int x = 0; x < grid.width; ++x) {
      const Gradient g = gradientAt(grid, x, y);
      const double stable =
          std::max(0.0, 1.0 - std::sqrt(g.dzdx * g.dzdx + g.dzdy * g.dzdy) / tanRepose);
      const double hollow =
          std::clamp(0.5 + concavityAt(grid, x, y) / (2.0 * Sediment::kConcavityScale), 0.0, 1.0);
      out.push_back(Sediment::kMaxM * stable * hollow);
    }
  return out;
}

} // namespace strahler::layers
