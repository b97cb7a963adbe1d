#pragma once

#include <cstdint>

// Fixed-width vectors of doubles for evaluating several samples at once (GCC vector
// extensions). Every lane performs the IEEE operations written, in the order written; the
// compiler maps them to SSE2, AVX2 or AVX-512 instructions without changing a result
// (no FMA contraction, see cmake/StrahlerTarget.cmake), so lane results equal scalar ones.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace strahler::base {

/// Number of samples evaluated together.
inline constexpr int kLanes = 8;
/// kLanes doubles.
using Doubles = double __attribute__((vector_size(8 * kLanes)));
/// kLanes lane masks (all bits set where a comparison holds), as comparisons of Doubles give.
using LaneMask = std::int64_t __attribute__((vector_size(8 * kLanes)));
/// kLanes 32-bit integers.
using Int32s = std::int32_t __attribute__((vector_size(4 * kLanes)));

/// Whether any lane of `m` is set (an OR across lanes by shuffles, kept in registers).
[[gnu::always_inline]] inline bool anyLane(LaneMask m) noexcept {
  static_assert(kLanes == 8);
  m |= __builtin_shuffle(m, LaneMask{4, 5, 6, 7, 0, 1, 2, 3});
  m |= __builtin_shuffle(m, LaneMask{2, 3, 0, 1, 6, 7, 4, 5});
  m |= __builtin_shuffle(m, LaneMask{1, 0, 3, 2, 5, 4, 7, 6});
  return m[0] != 0;
}

/// The least and the greatest lane of `v` (by shuffles, kept in registers).
[[gnu::always_inline]] inline void laneRange(Doubles v, double& least, double& greatest) noexcept {
  static_assert(kLanes == 8);
  Doubles lo = v, hi = v, s;
  s = __builtin_shuffle(lo, LaneMask{4, 5, 6, 7, 0, 1, 2, 3});
  lo = s < lo ? s : lo;
  s = __builtin_shuffle(hi, LaneMask{4, 5, 6, 7, 0, 1, 2, 3});
  hi = s > hi ? s : hi;
  s = __builtin_shuffle(lo, LaneMask{2, 3, 0, 1, 6, 7, 4, 5});
  lo = s < lo ? s : lo;
  s = __builtin_shuffle(hi, LaneMask{2, 3, 0, 1, 6, 7, 4, 5});
  hi = s > hi ? s : hi;
  s = __builtin_shuffle(lo, LaneMask{1, 0, 3, 2, 5, 4, 7, 6});
  lo = s < lo ? s : lo;
  s = __builtin_shuffle(hi, LaneMask{1, 0, 3, 2, 5, 4, 7, 6});
  hi = s > hi ? s : hi;
  least = lo[0];
  greatest = hi[0];
}

/// All lanes equal to v.
[[gnu::always_inline]] inline Doubles splat(double v) noexcept {
  return Doubles{} + v;
}

} // namespace strahler::base

#pragma GCC diagnostic pop
