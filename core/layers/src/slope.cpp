#include "strahler/layers/slope.h"

#include <cmath>
#include <numbers>

namespace strahler::layers {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

} // namespace

std::vector<double> slopeDegrees(const BorderedHeights& grid) {
  grid.check();
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height));
  for (int y = 0; y < grid.height; ++y)
    for (int x = 0; x < grid.width; ++x) {
      const Gradient g = gradientAt(grid, x, y);
      out.push_back(std::atan(std::sqrt(g.dzdx * g.dzdx + g.dzdy * g.dzdy)) * kDegrees);
    }
  return out;
}

std::vector<double> aspectDegrees(const BorderedHeights& grid) {
  grid.check();
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height));
  for (int y = 0; y < grid.height; ++y)
    for (int x = 0; x < grid.width; ++x) {
      const Gradient g = gradientAt(grid, x, y);
      if (g.dzdx == 0.0 && g.dzdy == 0.0) {
        out.push_back(kFlatAspect);
        continue;
      }
      // Downhill is −gradient; its compass bearing is atan2(east, north).
      double a = std::atan2(-g.dzdx, -g.dzdy) * kDegrees;
      if (a < 0.0)
        a += 360.0;
      out.push_back(a >= 360.0 ? 0.0 : a);
    }
  return out;
}

} // namespace strahler::layers
