#include "strahler/base/random.h"
#include "strahler/noise/lattice_noise.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <type_traits>

#pragma GCC diagnostic ignored "-Wpsabi"

namespace strahler::noise {
namespace {

using simd::kLanes;

/// The hash's multiplication as the AVX-512 kernels do it (vpmuludq): the product of each
/// lane's low 32 bits, here with other bits set above them, which atLanes() must not keep.
struct LowWordTimes {
  template <class V> [[gnu::always_inline]] V operator()(V h, std::uint32_t c) const noexcept {
    return ((h & 0xffffffffu) * c) ^ (std::uint64_t{0x5a5a5a5a} << 32);
  }
};

/// atLanes() at (xs, ys), W lanes at a time (kWideHash: the lattice hash in 64-bit lanes);
/// with a Times other than LatticeNoise::Multiply, given the floors and multiplying by Times.
template <int W, bool kWideHash = false, class Times = LatticeNoise::Multiply>
std::array<double, kLanes> lanes(const LatticeNoise& n, const double* xs, const double* ys) {
  using D = typename simd::Vectors<W>::Doubles;
  std::array<double, kLanes> out;
  for (int first = 0; first < kLanes; first += W) {
    D x, y;
    std::memcpy(&x, xs + first, sizeof x);
    std::memcpy(&y, ys + first, sizeof y);
    D v;
    if constexpr (std::is_same_v<Times, LatticeNoise::Multiply>) {
      v = n.atLanes<W, kWideHash>(x, y);
    } else {
      D fx, fy; // the floors, as the kernels take them by a rounding instruction
      for (int l = 0; l < W; ++l) {
        fx[l] = std::floor(x[l]);
        fy[l] = std::floor(y[l]);
      }
      v = n.atLanes<W, kWideHash>(x, y, fx, fy, Times{});
    }
    std::memcpy(out.data() + first, &v, sizeof v);
  }
  return out;
}

/// Every lane of atLanes<W>() equals at() bit for bit, on random points at many scales.
template <int W, bool kWideHash = false, class Times = LatticeNoise::Multiply>
void expectLanesEqualSinglePoints() {
  const LatticeNoise n(42);
  base::Rng rng(3);
  for (int trial = 0; trial < 2000; ++trial) {
    double xs[kLanes], ys[kLanes];
    const double scale = std::ldexp(1.0, static_cast<int>(rng.below(28)));
    for (int l = 0; l < kLanes; ++l) {
      xs[l] = rng.uniform(-scale, scale);
      ys[l] = rng.uniform(-scale, scale);
    }
    if (trial % 7 == 0)
      xs[trial % kLanes] = std::floor(xs[trial % kLanes]); // on a lattice line
    const std::array<double, kLanes> got = lanes<W, kWideHash, Times>(n, xs, ys);
    for (int l = 0; l < kLanes; ++l) {
      const double expected = n.at({xs[l], ys[l]});
      ASSERT_EQ(got[static_cast<std::size_t>(l)], expected)
          << "width " << W << " at " << xs[l] << ", " << ys[l];
    }
  }
}

TEST(LatticeNoise, LanesEqualSinglePointsBitForBit) {
  expectLanesEqualSinglePoints<8>();
  expectLanesEqualSinglePoints<8, true>(); // the AVX-512 kernels' hash in 64-bit lanes
  expectLanesEqualSinglePoints<8, true, LowWordTimes>(); // ... and their multiplication
  expectLanesEqualSinglePoints<4>();                     // the AVX2 kernels' width
  expectLanesEqualSinglePoints<2>();                     // the SSE2 kernels' width
}

TEST(LatticeNoise, ZeroOnTheLatticeAndBoundedBetween) {
  const LatticeNoise n(7);
  base::Rng rng(9);
  double lo = 0.0, hi = 0.0, sumSquares = 0.0;
  constexpr int kSamples = 100000;
  for (int i = 0; i < kSamples; ++i) {
    const double x = rng.uniform(-1000.0, 1000.0), y = rng.uniform(-1000.0, 1000.0);
    EXPECT_EQ(n.at({std::floor(x), std::floor(y)}), 0.0);
    const double v = n.at({x, y});
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sumSquares += v * v;
  }
  EXPECT_GE(lo, -1.0);
  EXPECT_LE(hi, 1.0);
  EXPECT_LT(lo, -0.4); // it does vary: both signs, a real spread
  EXPECT_GT(hi, 0.4);
  EXPECT_GT(std::sqrt(sumSquares / kSamples), 0.1);
}

TEST(LatticeNoise, ContinuousAcrossCells) {
  const LatticeNoise n(11);
  for (double x = -20.0; x < 20.0; x += 1.0)
    for (double y = -3.0; y < 3.0; y += 0.37) {
      EXPECT_NEAR(n.at({x - 1e-9, y}), n.at({x + 1e-9, y}), 1e-7);
      EXPECT_NEAR(n.at({y, x - 1e-9}), n.at({y, x + 1e-9}), 1e-7);
    }
}

TEST(LatticeNoise, SeedsGiveDifferentFieldsAndTheSameSeedTheSame) {
  const LatticeNoise a(1), b(2), again(1);
  int differ = 0;
  for (int i = 0; i < 100; ++i) {
    const geometry::Vec2 p{i * 0.731 + 0.1, i * 0.377 + 0.2};
    differ += a.at(p) != b.at(p);
    EXPECT_EQ(a.at(p), again.at(p));
  }
  EXPECT_GT(differ, 90);
}

TEST(LatticeNoise, OutOfRangeAndNonFiniteGiveZero) {
  const LatticeNoise n(5);
  EXPECT_EQ(n.at({3.0e9, 0.5}), 0.0);
  EXPECT_EQ(n.at({0.5, -3.0e9}), 0.0);
  EXPECT_EQ(n.at({std::nan(""), 0.5}), 0.0);
  EXPECT_EQ(n.at({0.5, INFINITY}), 0.0);
}

} // namespace
} // namespace strahler::noise
