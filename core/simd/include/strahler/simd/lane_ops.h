#pragma once

#include "strahler/simd/instruction_set.h"
#include "strahler/simd/lanes.h"

#include <array>
#include <cstddef>
#include <cstdint>
#if STRAHLER_SIMD_X86
#include <immintrin.h>
#endif

// Each operation that needs an instruction of one instruction set, by name: a portable
// version in simd::portable (GCC vector extensions and plain loops, for any target), and
// where x86 has an instruction for it, a version in simd::sse2, simd::avx2 or simd::avx512
// (only where STRAHLER_SIMD_X86) that gives the same bits. The x86 versions are always
// inlined and compiled for their set: call them only from code compiled for that set or a
// wider one (a `#pragma GCC target` region or a target attribute). Vectors of W doubles are
// Vectors<W>::Doubles; their masks Vectors<W>::Int64s (all bits set where true).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace strahler::simd {
namespace portable {

/// base[index[l]] lane by lane.
template <class D, class M> [[gnu::always_inline]] inline D gather(const double* base, M index) {
  D out;
  for (std::size_t l = 0; l < sizeof(D) / sizeof(double); ++l)
    out[l] = base[index[l]];
  return out;
}

/// v clamped to [0, 1] as `v < 0 ? 0 : v`, then `1 < v ? 1 : v` (a NaN stays).
template <class D> [[gnu::always_inline]] inline D clampUnit(D v) noexcept {
  const D zero{}, one = zero + 1.0;
  v = v < zero ? zero : v;
  return one < v ? one : v;
}

/// Bit l set where lane l of m is.
template <class M> [[gnu::always_inline]] inline unsigned maskBits(M m) noexcept {
  unsigned out = 0;
  for (std::size_t l = 0; l < sizeof(M) / sizeof(m[0]); ++l)
    out |= (m[l] != 0 ? 1u : 0u) << l;
  return out;
}

/// Stores, in order, each values[l] (l < width) whose bit l of `kept` is set to out and
/// returns how many: every value is written, the next one over it unless kept.
template <class T>
[[gnu::always_inline]] inline std::size_t compressStore(T* out, unsigned kept, const T* values,
                                                        std::size_t width) noexcept {
  std::size_t n = 0;
  for (std::size_t l = 0; l < width; ++l) {
    out[n] = values[l];
    n += (kept >> l) & 1u;
  }
  return n;
}

} // namespace portable

#if STRAHLER_SIMD_X86

namespace sse2 { // every x86-64: two doubles per register

/// portable::clampUnit() by minpd and maxpd (their operand order gives the same choices).
[[gnu::always_inline]] inline Vectors<2>::Doubles clampUnit(Vectors<2>::Doubles v) noexcept {
  return reinterpret_cast<Vectors<2>::Doubles>(
      _mm_min_pd(_mm_set1_pd(1.0), _mm_max_pd(_mm_setzero_pd(), reinterpret_cast<__m128d>(v))));
}
/// portable::maskBits() by movmskpd.
[[gnu::always_inline]] inline unsigned maskBits(Vectors<2>::Int64s m) noexcept {
  return static_cast<unsigned>(_mm_movemask_pd(reinterpret_cast<__m128d>(m)));
}

} // namespace sse2

namespace avx2 { // four doubles per register

/// portable::gather() by vgatherqpd.
[[gnu::always_inline, gnu::target("avx2")]] inline Vectors<4>::Doubles
gather(const double* base, Vectors<4>::Int64s index) noexcept {
  return reinterpret_cast<Vectors<4>::Doubles>(
      _mm256_i64gather_pd(base, reinterpret_cast<__m256i>(index), 8));
}
/// The floor of each lane by vroundpd (toward −∞, no exception flags).
[[gnu::always_inline, gnu::target("avx2")]] inline Vectors<4>::Doubles
floor(Vectors<4>::Doubles v) noexcept {
  return reinterpret_cast<Vectors<4>::Doubles>(
      _mm256_round_pd(reinterpret_cast<__m256d>(v), _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC));
}
/// portable::clampUnit() by vminpd and vmaxpd.
[[gnu::always_inline, gnu::target("avx2")]] inline Vectors<4>::Doubles
clampUnit(Vectors<4>::Doubles v) noexcept {
  return reinterpret_cast<Vectors<4>::Doubles>(_mm256_min_pd(
      _mm256_set1_pd(1.0), _mm256_max_pd(_mm256_setzero_pd(), reinterpret_cast<__m256d>(v))));
}
/// portable::maskBits() by vmovmskpd.
[[gnu::always_inline, gnu::target("avx2")]] inline unsigned
maskBits(Vectors<4>::Int64s m) noexcept {
  return static_cast<unsigned>(_mm256_movemask_pd(reinterpret_cast<__m256d>(m)));
}
/// For each mask of eight lanes, the indexes of its set lanes in order, three bits each (lane
/// i at bits 3i..3i+2; the rest 0).
inline constexpr std::array<std::uint32_t, 256> kPackedLanes = [] {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t mask = 0; mask < 256; ++mask) {
    std::uint32_t packed = 0, at = 0;
    for (std::uint32_t lane = 0; lane < 8; ++lane)
      if (mask & (1u << lane)) {
        packed |= lane << (3 * at);
        ++at;
      }
    table[mask] = packed;
  }
  return table;
}();
/// The permutation that moves the lanes set in `kept` (eight bits) to the front, in order.
[[gnu::always_inline, gnu::target("avx2")]] inline __m256i packingOrder(unsigned kept) noexcept {
  const __m256i shifts = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
  return _mm256_and_si256(
      _mm256_srlv_epi32(_mm256_set1_epi32(static_cast<int>(kPackedLanes[kept])), shifts),
      _mm256_set1_epi32(7));
}
/// portable::compressStore() of eight 32-bit values: the lanes of `order` (packingOrder() of
/// the kept lanes) permuted to the front of the register by vpermd, stored whole (eight
/// values written).
[[gnu::always_inline, gnu::target("avx2")]] inline void
compressStore(std::uint32_t* out, __m256i order, __m256i values) noexcept {
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm256_permutevar8x32_epi32(values, order));
}
/// The same for eight floats (vpermps).
[[gnu::always_inline, gnu::target("avx2")]] inline void compressStore(float* out, __m256i order,
                                                                      __m256 values) noexcept {
  _mm256_storeu_ps(out, _mm256_permutevar8x32_ps(values, order));
}

} // namespace avx2

namespace avx512 { // eight doubles per register (AVX-512F)

/// portable::gather() by vgatherqpd.
[[gnu::always_inline, gnu::target("avx512f")]] inline Vectors<8>::Doubles
gather(const double* base, Vectors<8>::Int64s index) noexcept {
  return reinterpret_cast<Vectors<8>::Doubles>(
      _mm512_i64gather_pd(reinterpret_cast<__m512i>(index), base, 8));
}
/// The floor of each lane by vrndscalepd (toward −∞, no exception flags).
[[gnu::always_inline, gnu::target("avx512f")]] inline Vectors<8>::Doubles
floor(Vectors<8>::Doubles v) noexcept {
  return reinterpret_cast<Vectors<8>::Doubles>(_mm512_roundscale_pd(
      reinterpret_cast<__m512d>(v), _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC));
}
/// portable::clampUnit() by vminpd and vmaxpd.
[[gnu::always_inline, gnu::target("avx512f")]] inline Vectors<8>::Doubles
clampUnit(Vectors<8>::Doubles v) noexcept {
  return reinterpret_cast<Vectors<8>::Doubles>(_mm512_min_pd(
      _mm512_set1_pd(1.0), _mm512_max_pd(_mm512_setzero_pd(), reinterpret_cast<__m512d>(v))));
}
/// portable::maskBits() by vptestmq.
[[gnu::always_inline, gnu::target("avx512f")]] inline unsigned
maskBits(Vectors<8>::Int64s m) noexcept {
  return _mm512_test_epi64_mask(reinterpret_cast<__m512i>(m), reinterpret_cast<__m512i>(m));
}
/// Whether any lane of v is at least `bound` (false for a NaN lane), from the comparison's
/// mask register: portable::maskBits(v >= bound) != 0.
[[gnu::always_inline, gnu::target("avx512f")]] inline bool anyAtLeast(Vectors<8>::Doubles v,
                                                                      double bound) noexcept {
  return _mm512_cmp_pd_mask(reinterpret_cast<__m512d>(v), _mm512_set1_pd(bound), _CMP_GE_OQ) != 0;
}
/// Each lane's low 32 bits times c by vpmuludq: the low 32 bits of each result equal those of
/// h · c (the high 32 bits differ: callers keep only the low ones).
[[gnu::always_inline, gnu::target("avx512f")]] inline Vectors<8>::UInt64s
mulLow32(Vectors<8>::UInt64s h, std::uint32_t c) noexcept {
  return reinterpret_cast<Vectors<8>::UInt64s>(
      _mm512_mul_epu32(reinterpret_cast<__m512i>(h), _mm512_set1_epi64(static_cast<long long>(c))));
}
/// portable::compressStore() of sixteen 32-bit values by vpcompressd into a register, stored
/// whole (sixteen values written: a compressing store to memory is slow on some CPUs).
[[gnu::always_inline, gnu::target("avx512f")]] inline std::size_t
compressStore(std::uint32_t* out, unsigned kept, __m512i values) noexcept {
  _mm512_storeu_si512(out, _mm512_maskz_compress_epi32(static_cast<__mmask16>(kept), values));
  return static_cast<std::size_t>(__builtin_popcount(kept & 0xffffu));
}
/// The same for sixteen floats.
[[gnu::always_inline, gnu::target("avx512f")]] inline std::size_t
compressStore(float* out, unsigned kept, __m512 values) noexcept {
  _mm512_storeu_ps(out, _mm512_maskz_compress_ps(static_cast<__mmask16>(kept), values));
  return static_cast<std::size_t>(__builtin_popcount(kept & 0xffffu));
}

} // namespace avx512

#endif // STRAHLER_SIMD_X86

} // namespace strahler::simd

#pragma GCC diagnostic pop
