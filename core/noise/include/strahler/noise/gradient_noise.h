#pragma once

#include "strahler/geometry/vec2.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace strahler::noise {
namespace detail {

// 16 unit gradients at multiples of 22.5 degrees.
inline constexpr double kGradients[16][2] = {{1.0, 0.0},
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

inline double fade(double t) noexcept {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

} // namespace detail

/// 2D gradient (Perlin) noise with a seeded permutation and a fixed table of 16 unit
/// gradients (no trigonometry at evaluation), so values are bit-identical everywhere.
/// Output is in about [-0.7, 0.7], zero at integer lattice points, period 256.
class GradientNoise {
public:
  /// Noise whose lattice is shuffled by `seed`.
  explicit GradientNoise(std::uint64_t seed) noexcept;

  /// Noise at p (lattice units). Defined here so that hot callers (the terrain's octave
  /// loop) inline it; the operations are the same wherever it is compiled (no FMA
  /// contraction), so values stay bit-identical.
  double at(geometry::Vec2 p) const noexcept {
    const double fx = std::floor(p.x), fy = std::floor(p.y);
    const auto ix = static_cast<std::size_t>(static_cast<std::int64_t>(fx) & 255);
    const auto iy = static_cast<std::size_t>(static_cast<std::int64_t>(fy) & 255);
    const double x = p.x - fx, y = p.y - fy;
    // The permutation is stored twice (512 entries), so row + column needs no wrap.
    const std::size_t r0 = perm_[ix], r1 = perm_[(ix + 1) & 255];
    const std::size_t iy1 = (iy + 1) & 255;
    const double* g00 = detail::kGradients[perm_[r0 + iy] & 15];
    const double* g10 = detail::kGradients[perm_[r1 + iy] & 15];
    const double* g01 = detail::kGradients[perm_[r0 + iy1] & 15];
    const double* g11 = detail::kGradients[perm_[r1 + iy1] & 15];
    const double n00 = g00[0] * x + g00[1] * y;
    const double n10 = g10[0] * (x - 1.0) + g10[1] * y;
    const double n01 = g01[0] * x + g01[1] * (y - 1.0);
    const double n11 = g11[0] * (x - 1.0) + g11[1] * (y - 1.0);
    const double u = detail::fade(x), v = detail::fade(y);
    const double a = n00 + u * (n10 - n00);
    const double b = n01 + u * (n11 - n01);
    return a + v * (b - a);
  }

  /// Fractal sum of `octaves` octaves: Σ gain^i · at(p · lacunarity^i), normalised so the
  /// amplitudes sum to 1.
  double fbm(geometry::Vec2 p, int octaves, double lacunarity = 2.0,
             double gain = 0.5) const noexcept;

private:
  std::array<std::uint8_t, 512> perm_{};
};

} // namespace strahler::noise
