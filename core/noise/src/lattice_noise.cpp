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
  const std::uint32_t hx0 = cx * kPrimeX, hx1 = (cx + 1u) * kPrimeX;
  const std::uint32_t hy0 = (cy * kPrimeY) ^ seed_, hy1 = ((cy + 1u) * kPrimeY) ^ seed_;
  const double x = p.x - fx, y = p.y - fy;
  const double x1 = x - 1.0, y1 = y - 1.0;
  auto dotGradient = [](std::uint32_t h, double dx, double dy) {
    const double* g = detail::kGradients[mix(h)];
    return g[0] * dx + g[1] * dy;
  };
  const double n00 = dotGradient(hx0 ^ hy0, x, y);
  const double n10 = dotGradient(hx1 ^ hy0, x1, y);
  const double n01 = dotGradient(hx0 ^ hy1, x, y1);
  const double n11 = dotGradient(hx1 ^ hy1, x1, y1);
  const double u = fade(x), v = fade(y);
  const double a = n00 + u * (n10 - n00);
  const double b = n01 + u * (n11 - n01);
  return a + v * (b - a);
}

} // namespace strahler::noise
