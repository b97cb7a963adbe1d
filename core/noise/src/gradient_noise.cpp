#include "strahler/noise/gradient_noise.h"

#include "strahler/base/random.h"

#include <cmath>

namespace strahler::noise {
namespace {

// 16 unit gradients at multiples of 22.5 degrees.
constexpr double kGradients[16][2] = {{1.0, 0.0},
                                      {0.9238795325, 0.3826834324},
                                      {0.7071067812, 0.7071067812},
                                      {0.3826834324, 0.9238795325},
                                      {0.0, 1.0},
                                      {-0.3826834324, 0.9238795325},
                                      {-0.7071067812, 0.7071067812},
                                      {-0.9238795325, 0.3826834324},
                                      {-1.0, 0.0},
                                      {-0.9238795325, -0.3826834324},
                                      {-0.7071067812, -0.7071067812},
                                      {-0.3826834324, -0.9238795325},
                                      {0.0, -1.0},
                                      {0.3826834324, -0.9238795325},
                                      {0.7071067812, -0.7071067812},
                                      {0.9238795325, -0.3826834324}};

double fade(double t) noexcept {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

} // namespace

GradientNoise::GradientNoise(std::uint64_t seed) noexcept {
  for (int i = 0; i < 256; ++i)
    perm_[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i);
  base::Rng rng(seed, 0x6e6f697365ull);
  for (std::uint32_t i = 255; i > 0; --i) {
    const std::uint32_t j = rng.below(i + 1);
    std::swap(perm_[i], perm_[j]);
  }
  for (std::size_t i = 0; i < 256; ++i)
    perm_[i + 256] = perm_[i];
}

double GradientNoise::at(geometry::Vec2 p) const noexcept {
  const double fx = std::floor(p.x), fy = std::floor(p.y);
  const auto ix = static_cast<std::size_t>(static_cast<std::int64_t>(fx) & 255);
  const auto iy = static_cast<std::size_t>(static_cast<std::int64_t>(fy) & 255);
  const double x = p.x - fx, y = p.y - fy;
  auto corner = [&](std::size_t cx, std::size_t cy, double dx, double dy) {
    const auto* g = kGradients[perm_[perm_[(ix + cx) & 255] + ((iy + cy) & 255)] & 15];
    return g[0] * dx + g[1] * dy;
  };
  const double n00 = corner(0, 0, x, y);
  const double n10 = corner(1, 0, x - 1.0, y);
  const double n01 = corner(0, 1, x, y - 1.0);
  const double n11 = corner(1, 1, x - 1.0, y - 1.0);
  const double u = fade(x), v = fade(y);
  const double a = n00 + u * (n10 - n00);
  const double b = n01 + u * (n11 - n01);
  return a + v * (b - a);
}

double GradientNoise::fbm(geometry::Vec2 p, int octaves, double lacunarity,
                          double gain) const noexcept {
  double sum = 0.0, amplitude = 1.0, norm = 0.0, frequency = 1.0;
  for (int i = 0; i < octaves; ++i) {
    // Offset each octave so lattice zeros do not line up.
    sum += amplitude * at(p * frequency + geometry::Vec2{17.31 * i, -9.73 * i});
    norm += amplitude;
    amplitude *= gain;
    frequency *= lacunarity;
  }
  return norm > 0.0 ? sum / norm : 0.0;
}

} // namespace strahler::noise
