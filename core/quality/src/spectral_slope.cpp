#include "strahler/quality/spectral_slope.h"

#include "line_fit.h"

#include "strahler/base/assert.h"
#include "strahler/quality/fft.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>

namespace strahler::quality {
namespace {

constexpr double kPi = 3.141592653589793;
constexpr int kBins = 15;
constexpr std::size_t kMinPointsPerBin = 4; // "more than 3"

/// numpy.hanning(n).
std::vector<double> hann(int n) {
  std::vector<double> w(std::size_t(std::max(n, 0)), 1.0);
  if (n > 1)
    for (int i = 0; i < n; ++i)
      w[std::size_t(i)] = 0.5 - 0.5 * std::cos(2.0 * kPi * double(i) / double(n - 1));
  return w;
}

/// numpy.fft.fftfreq(n, d): i / (n·d) for i < (n + 1) / 2, then (i − n) / (n·d).
std::vector<double> fftFrequencies(int n, double d) {
  std::vector<double> f(static_cast<std::size_t>(n));
  const double unit = 1.0 / (double(n) * d);
  const int positive = (n - 1) / 2 + 1;
  for (int i = 0; i < n; ++i)
    f[std::size_t(i)] = double(i < positive ? i : i - n) * unit;
  return f;
}

} // namespace

double spectralSlope(const std::vector<double>& heights, int width, int height, double cellSize) {
  STRAHLER_ASSERT(width > 0 && height > 0 &&
                      heights.size() == std::size_t(width) * std::size_t(height),
                  "spectralSlope: size mismatch");
  const std::size_t w = std::size_t(width), h = std::size_t(height);
  double mean = 0.0;
  for (double z : heights)
    mean += z;
  mean /= double(heights.size());
  const std::vector<double> hx = hann(width), hy = hann(height);
  std::vector<std::complex<double>> spectrum(heights.size());
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x)
      spectrum[y * w + x] = (heights[y * w + x] - mean) * (hy[y] * hx[x]);
  fft2(spectrum, width, height);

  const std::vector<double> fx = fftFrequencies(width, cellSize);
  const std::vector<double> fy = fftFrequencies(height, cellSize);
  const double kMin = 1.0 / kSpectralLongestWavelengthM, kMax = 1.0 / (4.0 * cellSize);
  std::vector<double> logK, logP;
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      const double k = std::hypot(fx[x], fy[y]);
      if (k > kMin && k < kMax) {
        logK.push_back(std::log10(k));
        logP.push_back(std::log10(std::norm(spectrum[y * w + x]) + 1e-30));
      }
    }
  if (logK.empty())
    return std::numeric_limits<double>::quiet_NaN();
  const double lo = *std::min_element(logK.begin(), logK.end());
  const double hi = *std::max_element(logK.begin(), logK.end());
  // numpy.linspace(lo, hi, 16): start + i·step, the last edge exactly hi.
  std::vector<double> edges(kBins + 1);
  const double step = (hi - lo) / kBins;
  for (int i = 0; i <= kBins; ++i)
    edges[std::size_t(i)] = lo + double(i) * step;
  edges[kBins] = hi;
  std::vector<double> sum(kBins, 0.0);
  std::vector<std::size_t> count(kBins, 0);
  for (std::size_t i = 0; i < logK.size(); ++i)
    for (std::size_t b = 0; b < std::size_t(kBins); ++b)
      if (logK[i] >= edges[b] && logK[i] < edges[b + 1]) {
        sum[b] += logP[i];
        ++count[b];
      }
  std::vector<double> bx, by;
  for (std::size_t b = 0; b < std::size_t(kBins); ++b)
    if (count[b] >= kMinPointsPerBin) {
      bx.push_back((edges[b] + edges[b + 1]) / 2.0);
      by.push_back(sum[b] / double(count[b]));
    }
  if (bx.size() <= 3)
    return std::numeric_limits<double>::quiet_NaN();
  return -detail::fitLine(bx, by).slope;
}

} // namespace strahler::quality
