#pragma once

#include "strahler/geometry/vec2.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

  /// Noise at two points (xs[i], ys[i]) into out[0], out[1]: each lane does the operations
  /// of at() in the same order (floor by truncation then correction, exact for |v| < 2^31;
  /// other inputs take at()), so results equal at()'s up to the sign of a zero.
  void at2(const double* xs, const double* ys, double* out) const noexcept {
#if defined(__SSE2__)
    const __m128d px = _mm_loadu_pd(xs), py = _mm_loadu_pd(ys);
    const __m128d limit = _mm_set1_pd(2147483647.0);
    const __m128d magnitude = _mm_set1_pd(-0.0);
    // Not-less-than is also true for NaN, which at() handles.
    const __m128d big = _mm_or_pd(_mm_cmpnlt_pd(_mm_andnot_pd(magnitude, px), limit),
                                  _mm_cmpnlt_pd(_mm_andnot_pd(magnitude, py), limit));
    if (_mm_movemask_pd(big) != 0) {
      out[0] = at({xs[0], ys[0]});
      out[1] = at({xs[1], ys[1]});
      return;
    }
    const __m128d one = _mm_set1_pd(1.0);
    const __m128d tx = _mm_cvtepi32_pd(_mm_cvttpd_epi32(px));
    const __m128d ty = _mm_cvtepi32_pd(_mm_cvttpd_epi32(py));
    const __m128d fx = _mm_sub_pd(tx, _mm_and_pd(_mm_cmpgt_pd(tx, px), one));
    const __m128d fy = _mm_sub_pd(ty, _mm_and_pd(_mm_cmpgt_pd(ty, py), one));
    const __m128i ixs = _mm_cvttpd_epi32(fx), iys = _mm_cvttpd_epi32(fy);
    alignas(16) std::int32_t ix[4], iy[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(ix), ixs);
    _mm_store_si128(reinterpret_cast<__m128i*>(iy), iys);
    const double* g[4][2]; // [corner 00, 10, 01, 11][lane]
    for (int l = 0; l < 2; ++l) {
      const auto cx = static_cast<std::size_t>(ix[l] & 255);
      const auto cy = static_cast<std::size_t>(iy[l] & 255);
      const std::size_t r0 = perm_[cx], r1 = perm_[(cx + 1) & 255];
      const std::size_t cy1 = (cy + 1) & 255;
      g[0][l] = detail::kGradients[perm_[r0 + cy] & 15];
      g[1][l] = detail::kGradients[perm_[r1 + cy] & 15];
      g[2][l] = detail::kGradients[perm_[r0 + cy1] & 15];
      g[3][l] = detail::kGradients[perm_[r1 + cy1] & 15];
    }
    const __m128d x = _mm_sub_pd(px, fx), y = _mm_sub_pd(py, fy);
    const __m128d x1 = _mm_sub_pd(x, one), y1 = _mm_sub_pd(y, one);
    auto dotg = [&](int c, __m128d dx, __m128d dy) {
      const __m128d gx = _mm_set_pd(g[c][1][0], g[c][0][0]);
      const __m128d gy = _mm_set_pd(g[c][1][1], g[c][0][1]);
      return _mm_add_pd(_mm_mul_pd(gx, dx), _mm_mul_pd(gy, dy));
    };
    const __m128d n00 = dotg(0, x, y), n10 = dotg(1, x1, y);
    const __m128d n01 = dotg(2, x, y1), n11 = dotg(3, x1, y1);
    auto fade = [](__m128d t) {
      // t * t * t * (t * (t * 6 - 15) + 10), in that order.
      const __m128d inner =
          _mm_add_pd(_mm_mul_pd(t, _mm_sub_pd(_mm_mul_pd(t, _mm_set1_pd(6.0)), _mm_set1_pd(15.0))),
                     _mm_set1_pd(10.0));
      return _mm_mul_pd(_mm_mul_pd(_mm_mul_pd(t, t), t), inner);
    };
    const __m128d u = fade(x), v = fade(y);
    const __m128d a = _mm_add_pd(n00, _mm_mul_pd(u, _mm_sub_pd(n10, n00)));
    const __m128d b = _mm_add_pd(n01, _mm_mul_pd(u, _mm_sub_pd(n11, n01)));
    _mm_storeu_pd(out, _mm_add_pd(a, _mm_mul_pd(v, _mm_sub_pd(b, a))));
#else
    out[0] = at({xs[0], ys[0]});
    out[1] = at({xs[1], ys[1]});
#endif
  }

  /// Fractal sum of `octaves` octaves: Σ gain^i · at(p · lacunarity^i), normalised so the
  /// amplitudes sum to 1.
  double fbm(geometry::Vec2 p, int octaves, double lacunarity = 2.0,
             double gain = 0.5) const noexcept;

private:
  std::array<std::uint8_t, 512> perm_{};
};

} // namespace strahler::noise
