#include "strahler/noise/lattice_noise.h"

#include "strahler/noise/gradient_noise.h"

namespace strahler::noise {

LatticeNoise::LatticeNoise(std::uint64_t seed) noexcept
    : seed_(static_cast<std::uint32_t>(seed ^ (seed >> 32))) {
  for (int i = 0; i < 16; ++i)
    for (int axis = 0; axis < 2; ++axis) {
      Table& t = axis == 0 ? gradientX_ : gradientY_;
      const double g = detail::kGradients[i][axis];
      t.by2[i / 2][i % 2] = g;
      t.by8[i / 8][i % 8] = g;
    }
  for (int i = 0; i < 4; ++i) {
    quadrantCos_[i] = detail::kGradients[i][0];
    quadrantSin_[i] = detail::kGradients[i][1];
  }
}

double LatticeNoise::at(geometry::Vec2 p) const noexcept {
  if (!(std::fabs(p.x) < kLaneLimit && std::fabs(p.y) < kLaneLimit))
    return 0.0;
  const double fx = std::floor(p.x), fy = std::floor(p.y);
  const auto cx = static_cast<std::uint32_t>(static_cast<std::int32_t>(fx));
  const auto cy = static_cast<std::uint32_t>(static_cast<std::int32_t>(fy));
  const auto word = [](std::uint32_t h) { return h; };
  return cellNoise(
      cx, cy, p.x - fx, p.y - fy,
      [&](std::uint32_t h, double dx, double dy) {
        const double* g = detail::kGradients[h >> 28];
        return g[0] * dx + g[1] * dy;
      },
      word);
}

} // namespace strahler::noise
