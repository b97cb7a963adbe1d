#include "strahler/noise/lattice_noise.h"

#include "strahler/noise/gradient_noise.h"

namespace strahler::noise {

LatticeNoise::LatticeNoise(std::uint64_t seed) noexcept
    : seed_(static_cast<std::uint32_t>(seed ^ (seed >> 32))) {
  for (int i = 0; i < 16; ++i) {
    gradientX_[i / base::kLanes][i % base::kLanes] = detail::kGradients[i][0];
    gradientY_[i / base::kLanes][i % base::kLanes] = detail::kGradients[i][1];
  }
}

double LatticeNoise::at(geometry::Vec2 p) const noexcept {
  if (!(std::fabs(p.x) < kLaneLimit && std::fabs(p.y) < kLaneLimit))
    return 0.0;
  const double fx = std::floor(p.x), fy = std::floor(p.y);
  const auto cx = static_cast<std::uint32_t>(static_cast<std::int32_t>(fx));
  const auto cy = static_cast<std::uint32_t>(static_cast<std::int32_t>(fy));
  return cellNoise(cx, cy, p.x - fx, p.y - fy, [](std::uint32_t h, double dx, double dy) {
    const double* g = detail::kGradients[mix(h)];
    return g[0] * dx + g[1] * dy;
  });
}

} // namespace strahler::noise
