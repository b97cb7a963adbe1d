#include "strahler/quality/fft.h"
#include "strahler/quality/spectral_slope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

namespace strahler::quality {
namespace {

/// A fractional-Brownian surface of n × n cells whose power spectrum falls as K^−β: complex
/// Gaussian coefficients of amplitude K^(−β/2), transformed back (the real part).
std::vector<double> fractalSurface(int n, double beta, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<std::complex<double>> spectrum(std::size_t(n) * std::size_t(n));
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double fx = x <= n / 2 ? x : x - n, fy = y <= n / 2 ? y : y - n;
      const double k = std::hypot(fx, fy);
      const double amplitude = k > 0 ? std::pow(k, -beta / 2) : 0.0;
      spectrum[std::size_t(y * n + x)] = amplitude * std::complex<double>(normal(rng), normal(rng));
    }
  // The inverse transform as the conjugate of the forward transform of the conjugate.
  for (auto& v : spectrum)
    v = std::conj(v);
  fft2(spectrum, n, n);
  std::vector<double> heights;
  for (const auto& v : spectrum)
    heights.push_back(1e4 * v.real() / double(n * n));
  return heights;
}

TEST(SpectralSlope, FractalSurfacesGiveTheirExponent) {
  // One surface scatters by ~0.1 and the Hann window adds a bias of +0.03..0.1 (numpy's
  // spectral_slope on 20 such surfaces: 2.55 for β 2.5, 3.06 for 3, 4.10 for 4): the mean of
  // 8 surfaces is within 0.15. A power-of-two side (radix-2) and the 7.5 km window at 30 m
  // (Bluestein).
  constexpr int kSurfaces = 8;
  for (int n : {256, 250})
    for (double beta : {2.5, 3.0, 4.0}) {
      double sum = 0.0;
      for (int seed = 1; seed <= kSurfaces; ++seed)
        sum += spectralSlope(fractalSurface(n, beta, unsigned(seed)), n, n, 30.0);
      EXPECT_NEAR(sum / kSurfaces, beta, 0.15) << "n " << n << " beta " << beta;
    }
}

TEST(SpectralSlope, DoesNotDependOnHeightScaleOrOffset) {
  std::vector<double> z = fractalSurface(128, 3.0, 1);
  const double base = spectralSlope(z, 128, 128, 30.0);
  for (double& v : z)
    v = 3.0 * v + 1000.0;
  EXPECT_NEAR(spectralSlope(z, 128, 128, 30.0), base, 1e-9);
}

TEST(SpectralSlope, UndefinedWithoutEnoughWavelengths) {
  // 2 km at 500 m cells leaves no wavelength between 4 cells and 2 km.
  EXPECT_TRUE(std::isnan(spectralSlope(fractalSurface(32, 3.0, 1), 32, 32, 500.0)));
}

} // namespace
} // namespace strahler::quality
