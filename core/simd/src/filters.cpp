#include "strahler/simd/filters.h"

#include "strahler/simd/lane_ops.h"

namespace strahler::simd {
namespace {

std::size_t keepWithinPortable(std::span<const float> keys, const std::uint32_t* ids, float low,
                               float high, std::uint32_t* out) noexcept {
  std::size_t n = 0;
  for (std::size_t k = 0; k < keys.size(); ++k) { // written, then kept or not
    out[n] = ids[k];
    n += static_cast<std::size_t>((keys[k] >= low) & (keys[k] <= high));
  }
  return n;
}

std::size_t keepDiscsPortable(const DiscColumns& discs, std::uint32_t first, std::size_t count,
                              const Box& box, std::uint32_t* ids, float* keys) noexcept {
  std::size_t n = 0;
  for (std::uint32_t i = first; i < first + count; ++i) { // written, then kept or not
    ids[n] = i;
    keys[n] = discs.key[i];
    const Vectors<2>::Doubles gap = gapsToBox(discs.x[i], discs.y[i], box);
    n += static_cast<std::size_t>(gap[0] * gap[0] + gap[1] * gap[1] <= discs.reach2[i]);
  }
  return n;
}

#if STRAHLER_SIMD_X86

/// The lanes of the low `count` (< 16) bits, all sixteen for count ≥ 16.
inline __mmask16 firstLanes(std::size_t count) noexcept {
  return count >= 16 ? static_cast<__mmask16>(0xffff) : static_cast<__mmask16>((1u << count) - 1u);
}

/// Sixteen keys per step: two comparisons into a mask, the kept ids compressed to the front.
__attribute__((target("avx512f"))) std::size_t keepWithinAvx512(std::span<const float> keys,
                                                                const std::uint32_t* ids, float low,
                                                                float high,
                                                                std::uint32_t* out) noexcept {
  const __m512 lo = _mm512_set1_ps(low), hi = _mm512_set1_ps(high);
  std::size_t n = 0;
  for (std::size_t k = 0; k < keys.size(); k += 16) {
    const __mmask16 valid = firstLanes(keys.size() - k);
    const __m512 key = _mm512_maskz_loadu_ps(valid, keys.data() + k);
    const __mmask16 kept = _mm512_mask_cmp_ps_mask(
        _mm512_mask_cmp_ps_mask(valid, key, lo, _CMP_GE_OQ), key, hi, _CMP_LE_OQ);
    n += avx512::compressStore(out + n, kept, _mm512_maskz_loadu_epi32(valid, ids + k));
  }
  return n;
}

/// Eight keys per step: the kept ids permuted to the front.
__attribute__((target("avx2"))) std::size_t keepWithinAvx2(std::span<const float> keys,
                                                           const std::uint32_t* ids, float low,
                                                           float high,
                                                           std::uint32_t* out) noexcept {
  const __m256 lo = _mm256_set1_ps(low), hi = _mm256_set1_ps(high);
  std::size_t n = 0, k = 0;
  for (; k + 8 <= keys.size(); k += 8) {
    const __m256 key = _mm256_loadu_ps(keys.data() + k);
    const __m256 within =
        _mm256_and_ps(_mm256_cmp_ps(key, lo, _CMP_GE_OQ), _mm256_cmp_ps(key, hi, _CMP_LE_OQ));
    const auto kept = static_cast<unsigned>(_mm256_movemask_ps(within));
    avx2::compressStore(out + n, avx2::packingOrder(kept),
                        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(ids + k)));
    n += static_cast<std::size_t>(__builtin_popcount(kept));
  }
  return n + keepWithinPortable(keys.subspan(k), ids + k, low, high, out + n);
}

/// Sixteen discs per step: the squared distances in two vectors of eight, the kept ids and
/// keys compressed to the front.
__attribute__((target("avx512f"))) std::size_t
keepDiscsAvx512(const DiscColumns& discs, std::uint32_t first, std::size_t count, const Box& box,
                std::uint32_t* ids, float* keys) noexcept {
  const __m512d minX = _mm512_set1_pd(box.minX), maxX = _mm512_set1_pd(box.maxX);
  const __m512d minY = _mm512_set1_pd(box.minY), maxY = _mm512_set1_pd(box.maxY);
  const __m512d zero = _mm512_setzero_pd();
  const __m512i lanes = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const auto meets = [&](std::size_t at, __mmask8 valid) __attribute__((target("avx512f"))) {
    const __m512d x = _mm512_maskz_loadu_pd(valid, discs.x + at);
    const __m512d y = _mm512_maskz_loadu_pd(valid, discs.y + at);
    const __m512d reach2 = _mm512_maskz_loadu_pd(valid, discs.reach2 + at);
    const __m512d gapX =
        _mm512_max_pd(_mm512_max_pd(_mm512_sub_pd(minX, x), _mm512_sub_pd(x, maxX)), zero);
    const __m512d gapY =
        _mm512_max_pd(_mm512_max_pd(_mm512_sub_pd(minY, y), _mm512_sub_pd(y, maxY)), zero);
    const __m512d distance2 = _mm512_add_pd(_mm512_mul_pd(gapX, gapX), _mm512_mul_pd(gapY, gapY));
    return _mm512_mask_cmp_pd_mask(valid, distance2, reach2, _CMP_LE_OQ);
  };
  std::size_t n = 0;
  for (std::size_t k = 0; k < count; k += 16) {
    const __mmask16 valid = firstLanes(count - k);
    const std::size_t at = first + k;
    const auto kept = static_cast<__mmask16>(
        meets(at, static_cast<__mmask8>(valid)) |
        (static_cast<unsigned>(meets(at + 8, static_cast<__mmask8>(valid >> 8))) << 8));
    avx512::compressStore(ids + n, kept,
                          _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(at)), lanes));
    n += avx512::compressStore(keys + n, kept, _mm512_maskz_loadu_ps(valid, discs.key + at));
  }
  return n;
}

/// Eight discs per step: the squared distances in two vectors of four, the kept ids and keys
/// permuted to the front.
__attribute__((target("avx2"))) std::size_t keepDiscsAvx2(const DiscColumns& discs,
                                                          std::uint32_t first, std::size_t count,
                                                          const Box& box, std::uint32_t* ids,
                                                          float* keys) noexcept {
  const __m256d minX = _mm256_set1_pd(box.minX), maxX = _mm256_set1_pd(box.maxX);
  const __m256d minY = _mm256_set1_pd(box.minY), maxY = _mm256_set1_pd(box.maxY);
  const __m256d zero = _mm256_setzero_pd();
  const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const auto meets = [&](std::size_t at) __attribute__((target("avx2"))) {
    const __m256d x = _mm256_loadu_pd(discs.x + at);
    const __m256d y = _mm256_loadu_pd(discs.y + at);
    const __m256d gapX =
        _mm256_max_pd(_mm256_max_pd(_mm256_sub_pd(minX, x), _mm256_sub_pd(x, maxX)), zero);
    const __m256d gapY =
        _mm256_max_pd(_mm256_max_pd(_mm256_sub_pd(minY, y), _mm256_sub_pd(y, maxY)), zero);
    const __m256d distance2 = _mm256_add_pd(_mm256_mul_pd(gapX, gapX), _mm256_mul_pd(gapY, gapY));
    return static_cast<unsigned>(_mm256_movemask_pd(
        _mm256_cmp_pd(distance2, _mm256_loadu_pd(discs.reach2 + at), _CMP_LE_OQ)));
  };
  std::size_t n = 0, k = 0;
  for (; k + 8 <= count; k += 8) {
    const std::size_t at = first + k;
    const unsigned kept = meets(at) | (meets(at + 4) << 4);
    const __m256i order = avx2::packingOrder(kept);
    avx2::compressStore(ids + n, order,
                        _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(at)), lanes));
    avx2::compressStore(keys + n, order, _mm256_loadu_ps(discs.key + at));
    n += static_cast<std::size_t>(__builtin_popcount(kept));
  }
  return n + keepDiscsPortable(discs, first + static_cast<std::uint32_t>(k), count - k, box,
                               ids + n, keys + n);
}

#endif // STRAHLER_SIMD_X86

} // namespace

std::size_t keepWithin(std::span<const float> keys, const std::uint32_t* ids, float low, float high,
                       std::uint32_t* out, InstructionSet set) {
#if STRAHLER_SIMD_X86
  if (set == InstructionSet::kAvx512)
    return keepWithinAvx512(keys, ids, low, high, out);
  if (set == InstructionSet::kAvx2)
    return keepWithinAvx2(keys, ids, low, high, out);
#endif
  static_cast<void>(set);
  return keepWithinPortable(keys, ids, low, high, out);
}

std::size_t keepDiscsMeeting(const DiscColumns& discs, std::uint32_t first, std::size_t count,
                             const Box& box, std::uint32_t* ids, float* keys, InstructionSet set) {
#if STRAHLER_SIMD_X86
  if (set == InstructionSet::kAvx512)
    return keepDiscsAvx512(discs, first, count, box, ids, keys);
  if (set == InstructionSet::kAvx2)
    return keepDiscsAvx2(discs, first, count, box, ids, keys);
#endif
  static_cast<void>(set);
  return keepDiscsPortable(discs, first, count, box, ids, keys);
}

} // namespace strahler::simd
