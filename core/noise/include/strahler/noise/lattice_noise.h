#pragma once

#include "strahler/geometry/vec2.h"
#include "strahler/simd/lanes.h"

#include <cmath>
#include <cstdint>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace strahler::noise {

/// 2D gradient (Perlin) noise whose lattice gradients come from an arithmetic hash of the
/// cell and the seed (no permutation table), so that simd::kLanes points are evaluated with
/// vector instructions only (atLanes()). The 16 gradients are unit vectors at multiples of
/// 22.5 degrees. Output in about [-0.7, 0.7], zero at lattice points, no period.
/// at() and atLanes() perform the same IEEE operations: lanes equal at() bit for bit.
class LatticeNoise {
public:
  /// Noise whose lattice is shuffled by `seed`.
  explicit LatticeNoise(std::uint64_t seed) noexcept;

  /// Largest |coordinate| atLanes() accepts (its lattice cells are 32-bit).
  static constexpr double kLaneLimit = 2.0e9;
  /// The lattice hash: corner (cx, cy) hashes to mix(cx·kPrimeX ^ cy·kPrimeY ^ seed) modulo
  /// 2^32, mix(h) = (h ^ h >> 15) · kMix (other lattices of the evaluator use it too).
  static constexpr std::uint32_t kPrimeX = 0x8da6b343u;
  static constexpr std::uint32_t kPrimeY = 0xd8163841u;
  static constexpr std::uint32_t kMix = 0x2c1b3c6du; ///< see kPrimeX

  /// Noise at p (lattice units); 0 where |p.x| or |p.y| ≥ kLaneLimit or not finite.
  double at(geometry::Vec2 p) const noexcept;

  /// Noise at simd::kLanes points (x[l], y[l]); every lane must satisfy |x|, |y| < kLaneLimit.
  [[gnu::always_inline]] simd::Doubles atLanes(simd::Doubles px, simd::Doubles py) const noexcept {
    return atLanes<simd::kLanes>(px, py);
  }

  /// The same at W points held in vectors of W lanes (W = 2, 4, 8: see simd::Vectors).
  /// kWideHash: the lattice hash in 64-bit lanes, each holding its 32-bit value (the same
  /// bits), for AVX-512 builds: GCC 12 widens eight 32-bit hashes to 64-bit gradient indices
  /// in two halves (four instructions per corner), and 64-bit lanes need no widening.
  template <int W, bool kWideHash = false>
  [[gnu::always_inline]] typename simd::Vectors<W>::Doubles
  atLanes(typename simd::Vectors<W>::Doubles px,
          typename simd::Vectors<W>::Doubles py) const noexcept {
    using Doubles = typename simd::Vectors<W>::Doubles;
    using Int32s = typename simd::Vectors<W>::Int32s;
    // floor by truncation then correction (exact below kLaneLimit).
    const Doubles tx = __builtin_convertvector(__builtin_convertvector(px, Int32s), Doubles);
    const Doubles ty = __builtin_convertvector(__builtin_convertvector(py, Int32s), Doubles);
    return atLanes<W, kWideHash>(px, py, tx > px ? tx - 1.0 : tx, ty > py ? ty - 1.0 : ty);
  }
  /// Multiplication of the lattice hash's words by a 32-bit constant (h · c).
  struct Multiply {
    template <class V> [[gnu::always_inline]] V operator()(V h, std::uint32_t c) const noexcept {
      return h * c;
    }
  };

  /// The same given the floors fx, fy of px, py (a caller whose instruction set has a
  /// rounding instruction takes them in one). `times(h, c)` multiplies the hash's words by a
  /// constant; with kWideHash, only each product's low 32 bits are kept, so a caller may
  /// multiply the low 32 bits of each lane alone (one instruction where 64-bit products take
  /// three); it must not be marked always_inline (it is inlined once this template is).
  template <int W, bool kWideHash, class Times = Multiply>
  [[gnu::always_inline]] typename simd::Vectors<W>::Doubles
  atLanes(typename simd::Vectors<W>::Doubles px, typename simd::Vectors<W>::Doubles py,
          typename simd::Vectors<W>::Doubles fx, typename simd::Vectors<W>::Doubles fy,
          Times&& times = {}) const noexcept {
    using Doubles = typename simd::Vectors<W>::Doubles;
    using Int32s = typename simd::Vectors<W>::Int32s;
    using Words = typename simd::Vectors<W>::Words;
    using UInt64s = typename simd::Vectors<W>::UInt64s;
    const auto dot = [this](auto h, Doubles dx, Doubles dy) __attribute__((always_inline)) {
      return dotGradient<W>(h, dx, dy);
    };
    if constexpr (kWideHash) {
      const UInt64s low = UInt64s{} + 0xffffffffu;
      const auto wrap = [low](UInt64s h) __attribute__((always_inline)) {
        return h & low;
      };
      using Int64s = typename simd::Vectors<W>::Int64s;
      const auto cx = reinterpret_cast<UInt64s>(__builtin_convertvector(fx, Int64s));
      const auto cy = reinterpret_cast<UInt64s>(__builtin_convertvector(fy, Int64s));
      return cellNoise(cx, cy, px - fx, py - fy, dot, wrap, times);
    } else {
      const Words cx = __builtin_convertvector(__builtin_convertvector(fx, Int32s), Words);
      const Words cy = __builtin_convertvector(__builtin_convertvector(fy, Int32s), Words);
      return cellNoise(
          cx, cy, px - fx, py - fy, dot, [](Words h) { return h; }, times);
    }
  }

private:
  /// 16 doubles, as 8 vectors of 2 and 2 of 8.
  struct Table {
    simd::Vectors<2>::Doubles by2[8];
    simd::Vectors<8>::Doubles by8[2];
  };
  /// Final mix of a cell's hash (one xor-shift-multiply round), 32 bits whose top 4
  /// (h >> 28) pick the gradient. `wrap` keeps 32 bits (the identity on 32-bit words): a
  /// product's low 32 bits depend only on its operands' low 32 bits, so wrapping after each
  /// operation suffices.
  template <class W, class Wrap, class Times>
  [[gnu::always_inline]] static W mix(W h, Wrap&& wrap, Times&& times) noexcept {
    h ^= h >> 15;
    return wrap(times(h, kMix));
  }
  /// Perlin's blend of the gradients of the four corners of lattice cell (cx, cy) at offset
  /// (x, y) inside it; dot(h, dx, dy) is gradient h >> 28 (of 16) of a corner's mixed hash h
  /// dotted with (dx, dy);
  /// `wrap` keeps 32 bits of a word (the identity on 32-bit words, a mask on 64-bit lanes).
  /// at() and atLanes() share it, so both perform the same operations.
  template <class D, class W, class Dot, class Wrap, class Times = Multiply>
  [[gnu::always_inline]] D cellNoise(W cx, W cy, D x, D y, Dot&& dot, Wrap&& wrap,
                                     Times&& times = {}) const noexcept {
    // (c + 1)·P = c·P + P modulo 2^32: one multiplication per axis.
    const W hx0 = wrap(times(cx, kPrimeX)), hx1 = wrap(hx0 + kPrimeX);
    const W rowHash = wrap(times(cy, kPrimeY));
    const W hy0 = rowHash ^ seed_, hy1 = wrap(rowHash + kPrimeY) ^ seed_;
    const D x1 = x - 1.0, y1 = y - 1.0;
    const D n00 = dot(mix(hx0 ^ hy0, wrap, times), x, y);
    const D n10 = dot(mix(hx1 ^ hy0, wrap, times), x1, y);
    const D n01 = dot(mix(hx0 ^ hy1, wrap, times), x, y1);
    const D n11 = dot(mix(hx1 ^ hy1, wrap, times), x1, y1);
    const D u = fade(x), v = fade(y);
    const D a = n00 + u * (n10 - n00);
    const D b = n01 + u * (n11 - n01);
    return a + v * (b - a);
  }
  template <class T> static T fade(T t) noexcept {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
  }
  /// Gradient h >> 28 (0 to 15) of mixed hashes h (32 bits, in W lanes of 32 or 64 bits)
  /// dotted with (x, y): a lookup in the table of 16 gradients held as vectors of W lanes, 2W
  /// entries per two-vector shuffle.
  template <int W, class H>
  [[gnu::always_inline]] typename simd::Vectors<W>::Doubles
  dotGradient(H h, typename simd::Vectors<W>::Doubles x,
              typename simd::Vectors<W>::Doubles y) const noexcept {
    using Doubles = typename simd::Vectors<W>::Doubles;
    using Int64s = typename simd::Vectors<W>::Int64s;
    if constexpr (W == 4) {
      static_assert(sizeof(h[0]) == 4, "four lanes hash in 32-bit words");
      // Gradient k is gradient k & 3 of the first quadrant, (p, s), turned by k >> 2 quarter
      // turns: the dot product is p·u + s·v with (u, v) = (x, y) turned back, and equals
      // gx·x + gy·y bit for bit (the same products up to sign, added in either order). Two
      // lookups in four-entry tables are cheaper here than one in sixteen. k's bits (q1 q0 r1
      // r0) are read where they lie: each hash is moved to the top of a 64-bit lane (widened by
      // a shuffle with zeros: one instruction, then a shift), so q1 is the sign bit.
      using UInt64s = typename simd::Vectors<W>::UInt64s;
      using Words8 = simd::Vectors<8>::Words;
      constexpr std::uint64_t kSign = std::uint64_t{1} << 63;
      const UInt64s top =
          reinterpret_cast<UInt64s>(__builtin_shufflevector(h, H{}, 0, 4, 1, 4, 2, 4, 3, 4)) << 32;
      const UInt64s q0 = top << 1; // q0 in the sign bit
      // Negations as a flip of the sign bit: u by q1, v by q1 xor q0 (bit 1 of q + 1).
      const auto signU = reinterpret_cast<Int64s>(top & kSign);
      const auto signV = reinterpret_cast<Int64s>((top ^ q0) & kSign);
      // Both lookups by one permutation of 32-bit words: double r's halves are words 2r and
      // 2r + 1, and the permutation reads only an index's low 3 bits; (top >> 59)'s are
      // r1 r0 and a bit of the hash below k, replaced by 0 in the low word, 1 in the high one.
      const auto above = reinterpret_cast<Words8>(top >> 59);
      const Words8 halves =
          (__builtin_shufflevector(above, above, 0, 0, 2, 2, 4, 4, 6, 6) & 0xfffffffeu) |
          Words8{0, 1, 0, 1, 0, 1, 0, 1};
      const auto p = reinterpret_cast<Doubles>(
          __builtin_shuffle(reinterpret_cast<Words8>(quadrantCos_), halves));
      const auto s = reinterpret_cast<Doubles>(
          __builtin_shuffle(reinterpret_cast<Words8>(quadrantSin_), halves));
      const Int64s swap = reinterpret_cast<Int64s>(q0) < 0; // blends read the sign bit alone
      Doubles u = swap ? y : x, v = swap ? x : y;
      u = reinterpret_cast<Doubles>(reinterpret_cast<Int64s>(u) ^ signU);
      v = reinterpret_cast<Doubles>(reinterpret_cast<Int64s>(v) ^ signV);
      return p * u + s * v;
    } else {
      const Int64s index = __builtin_convertvector(h >> 28, Int64s);
      const Doubles* gx = gradients<W>(gradientX_);
      const Doubles* gy = gradients<W>(gradientY_);
      Doubles ax = __builtin_shuffle(gx[0], gx[1], index),
              ay = __builtin_shuffle(gy[0], gy[1], index);
      for (int group = 1; group < 16 / (2 * W); ++group) {
        const Int64s in = index / (2 * W) == group;
        ax = in ? __builtin_shuffle(gx[2 * group], gx[2 * group + 1], index) : ax;
        ay = in ? __builtin_shuffle(gy[2 * group], gy[2 * group + 1], index) : ay;
      }
      return ax * x + ay * y;
    }
  }
  /// A table of 16 doubles as vectors of W lanes (W = 2 or 8; four lanes use the quadrant).
  template <int W>
  static const typename simd::Vectors<W>::Doubles* gradients(const Table& table) noexcept {
    static_assert(W == 2 || W == 8);
    if constexpr (W == 2)
      return table.by2;
    else
      return table.by8;
  }

  std::uint32_t seed_ = 0;
  // The x and the y components of the 16 gradients, as vectors of each width.
  Table gradientX_{}, gradientY_{};
  // The first quadrant's four gradients (cos, sin of 0°, 22.5°, 45°, 67.5°).
  simd::Vectors<4>::Doubles quadrantCos_{}, quadrantSin_{};
};

} // namespace strahler::noise

#pragma GCC diagnostic pop
