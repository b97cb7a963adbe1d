#pragma once

#include "strahler/base/lanes.h"
#include "strahler/geometry/vec2.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

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

  /// Largest |coordinate| atLanes() accepts.
  static constexpr double kLaneLimit = 2147483647.0;

  /// Noise at base::kLanes points (x[l], y[l]), each lane with the operations of at() in the
  /// same order (floor by truncation then correction), so lanes equal at() up to the sign of a
  /// zero. Requires |x|, |y| < kLaneLimit in every lane. When all lanes share one lattice cell
  /// (long wavelengths), the cell's gradients are looked up once.
  [[gnu::always_inline]] base::Doubles atLanes(base::Doubles px, base::Doubles py) const noexcept {
    using base::Doubles;
    using base::Int32s;
    using base::kLanes;
    const Doubles tx = __builtin_convertvector(__builtin_convertvector(px, Int32s), Doubles);
    const Doubles ty = __builtin_convertvector(__builtin_convertvector(py, Int32s), Doubles);
    const Doubles fx = tx > px ? tx - 1.0 : tx;
    const Doubles fy = ty > py ? ty - 1.0 : ty;
    const Int32s ix = __builtin_convertvector(fx, Int32s);
    const Int32s iy = __builtin_convertvector(fy, Int32s);
    alignas(64) double gx[4][kLanes], gy[4][kLanes]; // [corner 00, 10, 01, 11][lane]
    auto lookUp = [&](int l, int to) {
      const auto cx = static_cast<std::size_t>(ix[l] & 255);
      const auto cy = static_cast<std::size_t>(iy[l] & 255);
      const std::size_t r0 = perm_[cx], r1 = perm_[(cx + 1) & 255];
      const std::size_t cy1 = (cy + 1) & 255;
      const std::size_t corner[4] = {perm_[r0 + cy], perm_[r1 + cy], perm_[r0 + cy1],
                                     perm_[r1 + cy1]};
      for (int c = 0; c < 4; ++c) {
        const double* g = detail::kGradients[corner[c] & 15];
        for (int t = l; t < to; ++t) {
          gx[c][t] = g[0];
          gy[c][t] = g[1];
        }
      }
    };
    bool oneCell = true;
    for (int l = 1; l < kLanes; ++l)
      oneCell = oneCell && ix[l] == ix[0] && iy[l] == iy[0];
    if (oneCell)
      lookUp(0, kLanes);
    else
      for (int l = 0; l < kLanes; ++l)
        lookUp(l, l + 1);
    Doubles g[4][2];
    for (int c = 0; c < 4; ++c) {
      __builtin_memcpy(&g[c][0], gx[c], sizeof(Doubles));
      __builtin_memcpy(&g[c][1], gy[c], sizeof(Doubles));
    }
    const Doubles x = px - fx, y = py - fy;
    const Doubles x1 = x - 1.0, y1 = y - 1.0;
    const Doubles n00 = g[0][0] * x + g[0][1] * y;
    const Doubles n10 = g[1][0] * x1 + g[1][1] * y;
    const Doubles n01 = g[2][0] * x + g[2][1] * y1;
    const Doubles n11 = g[3][0] * x1 + g[3][1] * y1;
    auto fade = [](Doubles t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); };
    const Doubles u = fade(x), v = fade(y);
    const Doubles a = n00 + u * (n10 - n00);
    const Doubles b = n01 + u * (n11 - n01);
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

#pragma GCC diagnostic pop
