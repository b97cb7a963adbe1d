#include "strahler/tiling/candidate_filters.h"

#include <array>
#include <immintrin.h>

namespace strahler::tiling {
namespace {

using construction::InstructionSet;

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

/// The permutation that moves the lanes set in `mask` (eight bits) to the front, in order.
__attribute__((target("avx2"))) inline __m256i packingOrder(unsigned mask) noexcept {
  const __m256i shifts = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
  return _mm256_and_si256(
      _mm256_srlv_epi32(_mm256_set1_epi32(static_cast<int>(kPackedLanes[mask])), shifts),
      _mm256_set1_epi32(7));
}

/// The lanes of the low `count` (< 16) bits, all sixteen for count ≥ 16.
inline __mmask16 firstLanes(std::size_t count) noexcept {
  return count >= 16 ? static_cast<__mmask16>(0xffff) : static_cast<__mmask16>((1u << count) - 1u);
}

std::size_t keepKeysScalar(std::span<const float> keys, const std::uint32_t* ids, float low,
                           float high, std::uint32_t* out) noexcept {
  std::size_t n = 0;
  for (std::size_t k = 0; k < keys.size(); ++k) { // written, then kept or not
    out[n] = ids[k];
    n += static_cast<std::size_t>((keys[k] >= low) & (keys[k] <= high));
  }
  return n;
}

/// Sixteen keys per step: two comparisons into a mask, the kept ids packed to the front of a
/// register and stored whole (a compressing store to memory is slow on some CPUs).
__attribute__((target("avx512f"))) std::size_t keepKeysAvx512(std::span<const float> keys,
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
    const __m512i id = _mm512_maskz_loadu_epi32(valid, ids + k);
    _mm512_storeu_si512(out + n, _mm512_maskz_compress_epi32(kept, id));
    n += static_cast<std::size_t>(__builtin_popcount(kept));
  }
  return n;
}

/// Eight keys per step: the kept ids permuted to the front of a register and stored whole.
__attribute__((target("avx2"))) std::size_t keepKeysAvx2(std::span<const float> keys,
                                                         const std::uint32_t* ids, float low,
                                                         float high, std::uint32_t* out) noexcept {
  const __m256 lo = _mm256_set1_ps(low), hi = _mm256_set1_ps(high);
  std::size_t n = 0, k = 0;
  for (; k + 8 <= keys.size(); k += 8) {
    const __m256 key = _mm256_loadu_ps(keys.data() + k);
    const __m256 within =
        _mm256_and_ps(_mm256_cmp_ps(key, lo, _CMP_GE_OQ), _mm256_cmp_ps(key, hi, _CMP_LE_OQ));
    const auto kept = static_cast<unsigned>(_mm256_movemask_ps(within));
    const __m256i id = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(ids + k));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + n),
                        _mm256_permutevar8x32_epi32(id, packingOrder(kept)));
    n += static_cast<std::size_t>(__builtin_popcount(kept));
  }
  return n + keepKeysScalar(keys.subspan(k), ids + k, low, high, out + n);
}

std::size_t keepDiscsScalar(const TerrainDiscs& discs, std::uint32_t first, std::size_t count,
                            const geometry::Aabb& box, std::uint32_t* ids, float* keys) noexcept {
  std::size_t n = 0;
  for (std::uint32_t i = first; i < first + count; ++i) { // written, then kept or not
    ids[n] = i;
    keys[n] = discs.keyY[i];
    n += static_cast<std::size_t>(squaredDistanceToBox(discs.center(i), box) <= discs.reach2[i]);
  }
  return n;
}

/// Sixteen discs per step: the squared distances in two vectors of eight, the kept ids and
/// keys packed to the front of a register each and stored whole.
__attribute__((target("avx512f"))) std::size_t
keepDiscsAvx512(const TerrainDiscs& discs, std::uint32_t first, std::size_t count,
                const geometry::Aabb& box, std::uint32_t* ids, float* keys) noexcept {
  const __m512d minX = _mm512_set1_pd(box.min.x), maxX = _mm512_set1_pd(box.max.x);
  const __m512d minY = _mm512_set1_pd(box.min.y), maxY = _mm512_set1_pd(box.max.y);
  const __m512d zero = _mm512_setzero_pd();
  const __m512i lanes = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const auto meets = [&](std::size_t at, __mmask8 valid) __attribute__((target("avx512f"))) {
    const __m512d x = _mm512_maskz_loadu_pd(valid, discs.x.data() + at);
    const __m512d y = _mm512_maskz_loadu_pd(valid, discs.y.data() + at);
    const __m512d reach2 = _mm512_maskz_loadu_pd(valid, discs.reach2.data() + at);
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
    const __m512i id = _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(at)), lanes);
    _mm512_storeu_si512(ids + n, _mm512_maskz_compress_epi32(kept, id));
    const __m512 key = _mm512_maskz_loadu_ps(valid, discs.keyY.data() + at);
    _mm512_storeu_ps(keys + n, _mm512_maskz_compress_ps(kept, key));
    n += static_cast<std::size_t>(__builtin_popcount(kept));
  }
  return n;
}

/// Eight discs per step: the squared distances in two vectors of four, the kept ids and keys
/// permuted to the front of a register each and stored whole.
__attribute__((target("avx2"))) std::size_t
keepDiscsAvx2(const TerrainDiscs& discs, std::uint32_t first, std::size_t count,
              const geometry::Aabb& box, std::uint32_t* ids, float* keys) noexcept {
  const __m256d minX = _mm256_set1_pd(box.min.x), maxX = _mm256_set1_pd(box.max.x);
  const __m256d minY = _mm256_set1_pd(box.min.y), maxY = _mm256_set1_pd(box.max.y);
  const __m256d zero = _mm256_setzero_pd();
  const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const auto meets = [&](std::size_t at) __attribute__((target("avx2"))) {
    const __m256d x = _mm256_loadu_pd(discs.x.data() + at);
    const __m256d y = _mm256_loadu_pd(discs.y.data() + at);
    const __m256d gapX =
        _mm256_max_pd(_mm256_max_pd(_mm256_sub_pd(minX, x), _mm256_sub_pd(x, maxX)), zero);
    const __m256d gapY =
        _mm256_max_pd(_mm256_max_pd(_mm256_sub_pd(minY, y), _mm256_sub_pd(y, maxY)), zero);
    const __m256d distance2 = _mm256_add_pd(_mm256_mul_pd(gapX, gapX), _mm256_mul_pd(gapY, gapY));
    return static_cast<unsigned>(_mm256_movemask_pd(
        _mm256_cmp_pd(distance2, _mm256_loadu_pd(discs.reach2.data() + at), _CMP_LE_OQ)));
  };
  std::size_t n = 0, k = 0;
  for (; k + 8 <= count; k += 8) {
    const std::size_t at = first + k;
    const unsigned kept = meets(at) | (meets(at + 4) << 4);
    const __m256i order = packingOrder(kept);
    const __m256i id = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(at)), lanes);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(ids + n),
                        _mm256_permutevar8x32_epi32(id, order));
    _mm256_storeu_ps(keys + n,
                     _mm256_permutevar8x32_ps(_mm256_loadu_ps(discs.keyY.data() + at), order));
    n += static_cast<std::size_t>(__builtin_popcount(kept));
  }
  return n + keepDiscsScalar(discs, first + static_cast<std::uint32_t>(k), count - k, box, ids + n,
                             keys + n);
}

} // namespace

std::size_t keepKeysWithin(std::span<const float> keys, const std::uint32_t* ids, float low,
                           float high, std::uint32_t* out, InstructionSet set) {
  if (set == InstructionSet::kAvx512)
    return keepKeysAvx512(keys, ids, low, high, out);
  if (set == InstructionSet::kAvx2)
    return keepKeysAvx2(keys, ids, low, high, out);
  return keepKeysScalar(keys, ids, low, high, out);
}

TerrainDiscs::TerrainDiscs(std::span<const primitives::TerrainPrimitive> terrain) {
  for (const primitives::TerrainPrimitive& t : terrain) {
    x.push_back(t.center.x);
    y.push_back(t.center.y);
    reach2.push_back(t.radius * t.radius * (1.0 + 1e-9));
    keyY.push_back(static_cast<float>(t.center.y));
  }
}

std::size_t keepDiscsMeeting(const TerrainDiscs& discs, std::uint32_t first, std::size_t count,
                             const geometry::Aabb& box, std::uint32_t* ids, float* keys,
                             InstructionSet set) {
  if (set == InstructionSet::kAvx512)
    return keepDiscsAvx512(discs, first, count, box, ids, keys);
  if (set == InstructionSet::kAvx2)
    return keepDiscsAvx2(discs, first, count, box, ids, keys);
  return keepDiscsScalar(discs, first, count, box, ids, keys);
}

} // namespace strahler::tiling
