#include "ci_environment.h"

#include "strahler/simd/instruction_set.h"
#include "strahler/simd/lane_ops.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#pragma GCC diagnostic ignored "-Wpsabi"

namespace strahler::simd {
namespace {

/// Whether two doubles have the same bits.
bool sameBits(double a, double b) {
  std::uint64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

/// Values whose clamping and floors differ in every way: signs, zeros, NaN, ±∞, ties.
const std::vector<double>& awkward() {
  static const std::vector<double> values{-2.5,
                                          -1.0,
                                          -0.5,
                                          -0.0,
                                          0.0,
                                          0.25,
                                          0.5,
                                          1.0,
                                          1.5,
                                          3.75,
                                          -1e300,
                                          1e300,
                                          std::numeric_limits<double>::infinity(),
                                          -std::numeric_limits<double>::infinity(),
                                          std::numeric_limits<double>::quiet_NaN(),
                                          std::nextafter(1.0, 2.0)};
  return values;
}

/// W lanes of awkward() from `first` on (inlined: a vector of 64 bytes returned by a function
/// compiled without AVX-512 changes the ABI).
template <int W>
[[gnu::always_inline]] inline typename Vectors<W>::Doubles lanesFrom(std::size_t first) {
  typename Vectors<W>::Doubles v;
  for (int l = 0; l < W; ++l)
    v[l] = awkward()[(first + static_cast<std::size_t>(l)) % awkward().size()];
  return v;
}

TEST(InstructionSet, BaselineIsAlwaysSupportedAndTheDefaultIsSupported) {
  EXPECT_TRUE(supports(InstructionSet::kBaseline));
  EXPECT_TRUE(supports(instructionSet()));
#if !STRAHLER_SIMD_X86
  EXPECT_FALSE(supports(InstructionSet::kAvx2));
  EXPECT_FALSE(supports(InstructionSet::kAvx512));
  EXPECT_EQ(instructionSet(), InstructionSet::kBaseline);
#endif
}

TEST(InstructionSet, UseInstructionSetSwitchesOnlyToSupportedSets) {
  const InstructionSet saved = instructionSet();
  for (const InstructionSet set :
       {InstructionSet::kBaseline, InstructionSet::kAvx2, InstructionSet::kAvx512}) {
    EXPECT_EQ(useInstructionSet(set), supports(set));
    if (supports(set)) {
      EXPECT_EQ(instructionSet(), set);
    }
  }
  EXPECT_TRUE(useInstructionSet(saved));
}

TEST(PortableLaneOps, ClampUnitKeepsNaNAndOrdersZeros) {
  const auto v = portable::clampUnit(lanesFrom<8>(0));
  const double expected[] = {0.0, 0.0, 0.0, -0.0, 0.0, 0.25, 0.5, 1.0};
  for (int l = 0; l < 8; ++l)
    EXPECT_TRUE(sameBits(v[l], expected[l])) << l;
  EXPECT_TRUE(std::isnan(portable::clampUnit(lanesFrom<2>(14))[0]));
}

TEST(PortableLaneOps, MaskBitsAndCompressStoreFollowTheLanes) {
  const Vectors<4>::Int64s mask{-1, 0, -1, -1};
  EXPECT_EQ(portable::maskBits(mask), 0b1101u);
  const std::uint32_t values[] = {10, 11, 12, 13, 14};
  std::uint32_t out[5] = {};
  EXPECT_EQ(portable::compressStore(out, 0b10110u, values, 5), 3u);
  EXPECT_EQ(out[0], 11u);
  EXPECT_EQ(out[1], 12u);
  EXPECT_EQ(out[2], 14u);
}

#if STRAHLER_SIMD_X86

TEST(X86LaneOps, Sse2MatchesThePortableOperations) {
  for (std::size_t first = 0; first < awkward().size(); ++first) {
    const auto v = lanesFrom<2>(first);
    const auto a = sse2::clampUnit(v), b = portable::clampUnit(v);
    for (int l = 0; l < 2; ++l)
      EXPECT_TRUE(sameBits(a[l], b[l])) << first << " " << l;
    EXPECT_EQ(sse2::maskBits(v > 0.5), portable::maskBits(v > 0.5));
  }
}

[[gnu::target("avx2")]] void checkAvx2() {
  const double table[] = {1.0, 2.0, 4.0, 8.0, 16.0, 32.0};
  for (std::size_t first = 0; first < awkward().size(); ++first) {
    const auto v = lanesFrom<4>(first);
    const auto a = avx2::clampUnit(v), b = portable::clampUnit(v);
    const auto f = avx2::floor(v);
    for (int l = 0; l < 4; ++l) {
      EXPECT_TRUE(sameBits(a[l], b[l])) << first << " " << l;
      EXPECT_TRUE(sameBits(f[l], std::floor(v[l])) || (std::isnan(f[l]) && std::isnan(v[l])));
    }
    EXPECT_EQ(avx2::maskBits(v > 0.5), portable::maskBits(v > 0.5));
    const Vectors<4>::Int64s index{static_cast<std::int64_t>(first % 6), 5, 0, 3};
    const auto g = avx2::gather(table, index),
               p = portable::gather<Vectors<4>::Doubles>(table, index);
    for (int l = 0; l < 4; ++l)
      EXPECT_EQ(g[l], p[l]);
  }
  const std::uint32_t values[] = {20, 21, 22, 23, 24, 25, 26, 27};
  for (unsigned kept = 0; kept < 256; ++kept) {
    std::uint32_t got[8] = {}, want[8] = {};
    avx2::compressStore(got, avx2::packingOrder(kept),
                        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(values)));
    const std::size_t n = portable::compressStore(want, kept, values, 8);
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_EQ(got[i], want[i]) << kept;
  }
}

TEST(X86LaneOps, Avx2MatchesThePortableOperations) {
  if (!supports(InstructionSet::kAvx2)) {
    test_support::noteMissingHardware("X86LaneOps.Avx2MatchesThePortableOperations", "AVX2");
    GTEST_SKIP() << "this CPU has no AVX2";
  }
  checkAvx2();
}

[[gnu::target("avx512f")]] void checkAvx512() {
  const double table[] = {1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0};
  for (std::size_t first = 0; first < awkward().size(); ++first) {
    const auto v = lanesFrom<8>(first);
    const auto a = avx512::clampUnit(v), b = portable::clampUnit(v);
    const auto f = avx512::floor(v);
    for (int l = 0; l < 8; ++l) {
      EXPECT_TRUE(sameBits(a[l], b[l])) << first << " " << l;
      EXPECT_TRUE(sameBits(f[l], std::floor(v[l])) || (std::isnan(f[l]) && std::isnan(v[l])));
    }
    EXPECT_EQ(avx512::maskBits(v > 0.5), portable::maskBits(v > 0.5));
    EXPECT_EQ(avx512::anyAtLeast(v, 0.5), portable::maskBits(v >= 0.5) != 0);
    Vectors<8>::Int64s index;
    for (int l = 0; l < 8; ++l)
      index[l] = static_cast<std::int64_t>((first + 3 * static_cast<std::size_t>(l)) % 8);
    const auto g = avx512::gather(table, index),
               p = portable::gather<Vectors<8>::Doubles>(table, index);
    for (int l = 0; l < 8; ++l)
      EXPECT_EQ(g[l], p[l]);
  }
  const Vectors<8>::UInt64s h{0x123456789abcdefull, 1, 0xffffffffull, 0xfedcba9876543210ull, 7, 0,
                              0x80000000ull,        42};
  const auto product = avx512::mulLow32(h, 0x9e3779b9u), exact = h * 0x9e3779b9u;
  for (int l = 0; l < 8; ++l)
    EXPECT_EQ(product[l] & 0xffffffffu, exact[l] & 0xffffffffu) << l;
  std::uint32_t values[16];
  for (std::uint32_t i = 0; i < 16; ++i)
    values[i] = 100 + i;
  for (unsigned kept : {0u, 1u, 0x8000u, 0xffffu, 0xa5a5u, 0x1234u}) {
    std::uint32_t got[16] = {}, want[16] = {};
    const std::size_t n = avx512::compressStore(got, kept, _mm512_loadu_si512(values));
    ASSERT_EQ(n, portable::compressStore(want, kept, values, 16));
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_EQ(got[i], want[i]) << kept;
  }
}

TEST(X86LaneOps, Avx512MatchesThePortableOperations) {
  if (!supports(InstructionSet::kAvx512)) {
    test_support::noteMissingHardware("X86LaneOps.Avx512MatchesThePortableOperations", "AVX-512");
    GTEST_SKIP() << "this CPU has no AVX-512";
  }
  checkAvx512();
}

#endif // STRAHLER_SIMD_X86

} // namespace
} // namespace strahler::simd
