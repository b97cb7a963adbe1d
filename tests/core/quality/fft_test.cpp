#include "strahler/quality/fft.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

namespace strahler::quality {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = 3.141592653589793;

/// The O(n²) definition, X[k] = Σ x[j]·exp(−2πi·jk/n).
std::vector<Complex> naiveDft(const std::vector<Complex>& x) {
  const std::size_t n = x.size();
  std::vector<Complex> out(n);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < n; ++j)
      out[k] += x[j] * std::polar(1.0, -2.0 * kPi * double((j * k) % n) / double(n));
  return out;
}

std::vector<Complex> randomValues(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<Complex> x(n);
  for (Complex& v : x)
    v = {normal(rng), normal(rng)};
  return x;
}

TEST(Fft, EveryLengthMatchesTheDefinition) {
  // Powers of two (radix-2), primes and composites (Bluestein), and the window sizes of
  // analyze (250 = 7.5 km at 30 m, 167 = 5 km at 30 m, 82 = 7.5 km at 91.67 m).
  for (std::size_t n : {1u, 2u, 3u, 4u, 5u, 7u, 8u, 12u, 16u, 17u, 64u, 82u, 97u, 167u, 250u}) {
    const std::vector<Complex> x = randomValues(n, unsigned(n));
    const std::vector<Complex> expected = naiveDft(x);
    std::vector<Complex> got = x;
    fft(got);
    double scale = 0.0;
    for (const Complex& v : expected)
      scale = std::max(scale, std::abs(v));
    for (std::size_t k = 0; k < n; ++k)
      EXPECT_NEAR(std::abs(got[k] - expected[k]), 0.0, 1e-12 * scale + 1e-12)
          << "n " << n << " k " << k;
  }
}

TEST(Fft, TwoDimensionsTransformRowsThenColumns) {
  const int width = 6, height = 5;
  std::vector<Complex> grid = randomValues(std::size_t(width * height), 3);
  std::vector<Complex> expected(grid.size());
  for (int ky = 0; ky < height; ++ky)
    for (int kx = 0; kx < width; ++kx)
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
          expected[std::size_t(ky * width + kx)] +=
              grid[std::size_t(y * width + x)] *
              std::polar(1.0, -2.0 * kPi * (double(kx * x) / width + double(ky * y) / height));
  fft2(grid, width, height);
  for (std::size_t i = 0; i < grid.size(); ++i)
    EXPECT_NEAR(std::abs(grid[i] - expected[i]), 0.0, 1e-11) << i;
}

TEST(Fft, ASineHasItsPowerAtItsFrequency) {
  const std::size_t n = 250;
  std::vector<Complex> x(n);
  for (std::size_t j = 0; j < n; ++j)
    x[j] = std::cos(2.0 * kPi * 7.0 * double(j) / double(n));
  fft(x);
  for (std::size_t k = 0; k < n; ++k)
    EXPECT_NEAR(std::abs(x[k]), (k == 7 || k == n - 7) ? double(n) / 2 : 0.0, 1e-9) << k;
}

} // namespace
} // namespace strahler::quality
