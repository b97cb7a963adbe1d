#include "strahler/quality/fft.h"

#include "strahler/base/assert.h"

#include <cmath>
#include <cstddef>

namespace strahler::quality {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = 3.141592653589793;

bool isPowerOfTwo(std::size_t n) {
  return n != 0 && (n & (n - 1)) == 0;
}

/// Iterative radix-2 transform of a power-of-two length; `sign` −1 forward, +1 inverse
/// (unnormalised).
void radix2(std::vector<Complex>& a, int sign) {
  const std::size_t n = a.size();
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1)
      j ^= bit;
    j ^= bit;
    if (i < j)
      std::swap(a[i], a[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    // Twiddles computed directly (not by repeated multiplication) to keep the error at ~1 ulp.
    const std::size_t half = len / 2;
    std::vector<Complex> twiddle(half);
    for (std::size_t k = 0; k < half; ++k) {
      const double angle = sign * 2.0 * kPi * double(k) / double(len);
      twiddle[k] = Complex(std::cos(angle), std::sin(angle));
    }
    for (std::size_t start = 0; start < n; start += len)
      for (std::size_t k = 0; k < half; ++k) {
        const Complex u = a[start + k];
        const Complex v = a[start + k + half] * twiddle[k];
        a[start + k] = u + v;
        a[start + k + half] = u - v;
      }
  }
}

/// Bluestein: X[k] = conj(w[k]) · Σ_j (x[j]·conj(w[j])) · w[k−j] with w[m] = exp(iπm²/n),
/// the convolution done by power-of-two transforms of length ≥ 2n − 1.
void bluestein(std::vector<Complex>& x) {
  const std::size_t n = x.size();
  std::size_t m = 1;
  while (m < 2 * n - 1)
    m <<= 1;
  std::vector<Complex> chirp(n);
  for (std::size_t k = 0; k < n; ++k) {
    // k² mod 2n keeps the angle small and exact for large k.
    const std::size_t k2 = (k * k) % (2 * n);
    const double angle = kPi * double(k2) / double(n);
    chirp[k] = Complex(std::cos(angle), std::sin(angle));
  }
  std::vector<Complex> a(m), b(m);
  for (std::size_t k = 0; k < n; ++k)
    a[k] = x[k] * std::conj(chirp[k]);
  b[0] = chirp[0];
  for (std::size_t k = 1; k < n; ++k)
    b[k] = b[m - k] = chirp[k];
  radix2(a, -1);
  radix2(b, -1);
  for (std::size_t k = 0; k < m; ++k)
    a[k] *= b[k];
  radix2(a, +1);
  for (std::size_t k = 0; k < n; ++k)
    x[k] = a[k] * std::conj(chirp[k]) / double(m);
}

} // namespace

void fft(std::vector<Complex>& values) {
  if (values.size() <= 1)
    return;
  if (isPowerOfTwo(values.size()))
    radix2(values, -1);
  else
    bluestein(values);
}

void fft2(std::vector<Complex>& values, int width, int height) {
  STRAHLER_ASSERT(width >= 0 && height >= 0 &&
                      values.size() == std::size_t(width) * std::size_t(height),
                  "fft2: size mismatch");
  const std::size_t w = std::size_t(width), h = std::size_t(height);
  std::vector<Complex> line(w);
  for (std::size_t y = 0; y < h; ++y) {
    for (std::size_t x = 0; x < w; ++x)
      line[x] = values[y * w + x];
    fft(line);
    for (std::size_t x = 0; x < w; ++x)
      values[y * w + x] = line[x];
  }
  line.resize(h);
  for (std::size_t x = 0; x < w; ++x) {
    for (std::size_t y = 0; y < h; ++y)
      line[y] = values[y * w + x];
    fft(line);
    for (std::size_t y = 0; y < h; ++y)
      values[y * w + x] = line[y];
  }
}

} // namespace strahler::quality
