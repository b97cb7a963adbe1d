#include "strahler/tiling/key_filter.h"

#include <array>
#include <immintrin.h>

namespace strahler::tiling {
namespace {

/// One key at a time: the id is written, then kept or not (no branch per key).
std::size_t keepScalar(std::span<const float> keys, const std::uint32_t* ids, float low, float high,
                       std::uint32_t* out) noexcept {
  std::size_t n = 0;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    out[n] = ids[k];
    n += static_cast<std::size_t>((keys[k] >= low) & (keys[k] <= high));
  }
  return n;
}

/// Sixteen keys per step: two comparisons into a mask, the kept ids packed to the front of a
/// register and stored whole (a compressing store to memory is slow on some CPUs).
__attribute__((target("avx512f"))) std::size_t keepAvx512(std::span<const float> keys,
                                                          const std::uint32_t* ids, float low,
                                                          float high, std::uint32_t* out) noexcept {
  const __m512 lo = _mm512_set1_ps(low), hi = _mm512_set1_ps(high);
  std::size_t n = 0;
  for (std::size_t k = 0; k < keys.size(); k += 16) {
    const std::size_t left = keys.size() - k;
    const __mmask16 valid =
        left >= 16 ? static_cast<__mmask16>(0xffff) : static_cast<__mmask16>((1u << left) - 1u);
    const __m512 key = _mm512_maskz_loadu_ps(valid, keys.data() + k);
    const __mmask16 kept = _mm512_mask_cmp_ps_mask(
        _mm512_mask_cmp_ps_mask(valid, key, lo, _CMP_GE_OQ), key, hi, _CMP_LE_OQ);
    const __m512i id = _mm512_maskz_loadu_epi32(valid, ids + k);
    _mm512_storeu_si512(out + n, _mm512_maskz_compress_epi32(kept, id));
    n += static_cast<std::size_t>(__builtin_popcount(kept));
  }
  return n;
}

/// For each mask of eight lanes, the indexes of its set lanes in order, three bits each (lane
/// i at bits 3i..3i+2; the rest 0).
constexpr std::array<std::uint32_t, 256> kPackedLanes = [] {
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

/// Eight keys per step: the kept lanes' indexes unpacked from kPackedLanes by variable shifts,
/// the ids permuted to the front of a register and stored whole.
__attribute__((target("avx2"))) std::size_t keepAvx2(std::span<const float> keys,
                                                     const std::uint32_t* ids, float low,
                                                     float high, std::uint32_t* out) noexcept {
  const __m256 lo = _mm256_set1_ps(low), hi = _mm256_set1_ps(high);
  const __m256i shifts = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
  const __m256i lowBits = _mm256_set1_epi32(7);
  std::size_t n = 0, k = 0;
  for (; k + 8 <= keys.size(); k += 8) {
    const __m256 key = _mm256_loadu_ps(keys.data() + k);
    const __m256 within =
        _mm256_and_ps(_mm256_cmp_ps(key, lo, _CMP_GE_OQ), _mm256_cmp_ps(key, hi, _CMP_LE_OQ));
    const auto kept = static_cast<unsigned>(_mm256_movemask_ps(within));
    const __m256i order = _mm256_and_si256(
        _mm256_srlv_epi32(_mm256_set1_epi32(static_cast<int>(kPackedLanes[kept])), shifts),
        lowBits);
    const __m256i id = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(ids + k));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + n),
                        _mm256_permutevar8x32_epi32(id, order));
    n += static_cast<std::size_t>(__builtin_popcount(kept));
  }
  return n + keepScalar(keys.subspan(k), ids + k, low, high, out + n);
}

} // namespace

std::size_t keepKeysWithin(std::span<const float> keys, const std::uint32_t* ids, float low,
                           float high, std::uint32_t* out, construction::InstructionSet set) {
  if (set == construction::InstructionSet::kAvx512)
    return keepAvx512(keys, ids, low, high, out);
  if (set == construction::InstructionSet::kAvx2)
    return keepAvx2(keys, ids, low, high, out);
  return keepScalar(keys, ids, low, high, out);
}

} // namespace strahler::tiling
