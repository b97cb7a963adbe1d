#include "strahler/layers/slope.h"

#include <cmath>
#include <numbers>

namespace strahler::layers {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

} // namespace

std::vector<double> slopeDegrees(const BorderedHeights& grid) {
  return perPixel(
      grid, [&](int x, int y) { return std::atan(tanSlope(gradientAt(grid, x, y))) * kDegrees; });
}

std::vector<double> aspectDegrees(const BorderedHeights& grid) {
  return perPixel(grid, [&](int x, int y) {
    const Gradient g = gradientAt(grid, x, y);
    if (g.dzdx == 0.0 && g.dzdy == 0.0)
      return kFlatAspect;
    // Downhill is −gradient; its compass bearing is atan2(east, north).
    double a = std::atan2(-g.dzdx, -g.dzdy) * kDegrees;
    if (a < 0.0)
      a += 360.0;
    return a >= 360.0 ? 0.0 : a;
  });
}

} // namespace strahler::layers
