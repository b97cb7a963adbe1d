#pragma once

#include "strahler/base/lanes.h"
#include "strahler/geometry/vec2.h"

#include <cmath>
#include <cstdint>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace strahler::noise {

/// 2D gradient (Perlin) noise whose lattice gradients come from an arithmetic hash of the
/// cell and the seed (no permutation table), so that base::kLanes points are evaluated with
/// vector instructions only (atLanes()). The 16 gradients are unit vectors at multiples of
/// 22.5 degrees. Output in about [-0.7, 0.7], zero at lattice points, no period.
/// at() and atLanes() perform the same IEEE operations: lanes equal at() bit for bit.
class LatticeNoise {
public:
  /// Noise whose lattice is shuffled by `seed`.
  explicit LatticeNoise(std::uint64_t seed) noexcept;

  /// Largest |coordinate| atLanes() accepts (its lattice cells are 32-bit).
  static constexpr double kLaneLimit = 2.0e9;

  /// Noise at p (lattice units); 0 where |p.x| or |p.y| ≥ kLaneLimit or not finite.
  double at(geometry::Vec2 p) const noexcept;

  /// Noise at base::kLanes points (x[l], y[l]); every lane must satisfy |x|, |y| < kLaneLimit.
  [[gnu::always_inline]] base::Doubles atLanes(base::Doubles px, base::Doubles py) const noexcept {
    using base::Doubles;
    // floor by truncation then correction (exact below kLaneLimit).
    const Doubles tx = __builtin_convertvector(__builtin_convertvector(px, base::Int32s), Doubles);
    const Doubles ty = __builtin_convertvector(__builtin_convertvector(py, base::Int32s), Doubles);
    const Doubles fx = tx > px ? tx - 1.0 : tx;
    const Doubles fy = ty > py ? ty - 1.0 : ty;
    const Words cx = __builtin_convertvector(__builtin_convertvector(fx, base::Int32s), Words);
    const Words cy = __builtin_convertvector(__builtin_convertvector(fy, base::Int32s), Words);
    return cellNoise(
        cx, cy, px - fx,
        py - fy, [this](Words h, Doubles dx, Doubles dy) __attribute__((always_inline)) {
          return dotGradient(h, dx, dy);
        });
  }

private:
  /// base::kLanes unsigned 32-bit words.
  using Words = std::uint32_t __attribute__((vector_size(4 * base::kLanes)));
  static constexpr std::uint32_t kPrimeX = 0x8da6b343u;
  static constexpr std::uint32_t kPrimeY = 0xd8163841u;

  /// Final mix of a cell's hash (one xor-shift-multiply round); its top 4 bits pick the
  /// gradient.
  template <class W> static W mix(W h) noexcept {
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    return h >> 28;
  }
  /// Perlin's blend of the gradients of the four corners of lattice cell (cx, cy) at offset
  /// (x, y) inside it; dot(h, dx, dy) is the gradient picked by hash h dotted with (dx, dy).
  /// at() and atLanes() share it, so both perform the same operations.
  template <class D, class W, class Dot>
  [[gnu::always_inline]] D cellNoise(W cx, W cy, D x, D y, Dot&& dot) const noexcept {
    const W hx0 = cx * kPrimeX, hx1 = (cx + 1u) * kPrimeX;
    const W hy0 = (cy * kPrimeY) ^ seed_, hy1 = ((cy + 1u) * kPrimeY) ^ seed_;
    const D x1 = x - 1.0, y1 = y - 1.0;
    const D n00 = dot(hx0 ^ hy0, x, y);
    const D n10 = dot(hx1 ^ hy0, x1, y);
    const D n01 = dot(hx0 ^ hy1, x, y1);
    const D n11 = dot(hx1 ^ hy1, x1, y1);
    const D u = fade(x), v = fade(y);
    const D a = n00 + u * (n10 - n00);
    const D b = n01 + u * (n11 - n01);
    return a + v * (b - a);
  }
  template <class T> static T fade(T t) noexcept {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
  }
  [[gnu::always_inline]] base::Doubles dotGradient(Words h, base::Doubles x,
                                                   base::Doubles y) const noexcept {
    const auto index = __builtin_convertvector(mix(h), base::LaneMask);
    return __builtin_shuffle(gradientX_[0], gradientX_[1], index) * x +
           __builtin_shuffle(gradientY_[0], gradientY_[1], index) * y;
  }

  std::uint32_t seed_ = 0;
  // The 16 gradients: x components of entries 0-7 and 8-15, then the y components.
  base::Doubles gradientX_[2]{}, gradientY_[2]{};
};

} // namespace strahler::noise

#pragma GCC diagnostic pop
