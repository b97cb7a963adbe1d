#pragma once

#include <cstdint>

// Fixed-width vectors of doubles for evaluating several samples at once (GCC vector
// extensions). Every lane performs the IEEE operations written, in the order written; the
// compiler maps them to SSE2, AVX2 or AVX-512 instructions without changing a result
// (no FMA contraction, see cmake/StrahlerTarget.cmake), so lane results equal scalar ones.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace strahler::simd {

/// Number of samples evaluated together.
inline constexpr int kLanes = 8;

/// Vectors of W lanes, W = 2, 4 or 8: one SSE2, AVX2 or AVX-512 register of doubles (wider
/// vectors than the registers get their comparisons split into scalar code). Specialised per
/// width: GCC ignores a vector_size that depends on a template parameter.
template <int W> struct Vectors;
template <> struct Vectors<2> {
  using Doubles = double __attribute__((vector_size(16)));
  using Int64s = std::int64_t __attribute__((vector_size(16)));
  using UInt64s = std::uint64_t __attribute__((vector_size(16)));
  using Int32s = std::int32_t __attribute__((vector_size(8)));
  using Words = std::uint32_t __attribute__((vector_size(8)));
};
template <> struct Vectors<4> {
  using Doubles = double __attribute__((vector_size(32)));
  using Int64s = std::int64_t __attribute__((vector_size(32)));
  using UInt64s = std::uint64_t __attribute__((vector_size(32)));
  using Int32s = std::int32_t __attribute__((vector_size(16)));
  using Words = std::uint32_t __attribute__((vector_size(16)));
};
template <> struct Vectors<8> {
  using Doubles = double __attribute__((vector_size(64)));
  using Int64s = std::int64_t __attribute__((vector_size(64)));
  using UInt64s = std::uint64_t __attribute__((vector_size(64)));
  using Int32s = std::int32_t __attribute__((vector_size(32)));
  using Words = std::uint32_t __attribute__((vector_size(32)));
};

/// kLanes doubles.
using Doubles = Vectors<kLanes>::Doubles;

} // namespace strahler::simd

#pragma GCC diagnostic pop
