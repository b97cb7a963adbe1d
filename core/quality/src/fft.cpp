#include "strahler/quality/fft.h"

#include "strahler/base/assert.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace strahler::quality {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = 3.141592653589793;

bool isPowerOfTwo(std::size_t n) {
  return n != 0 && (n & (n - 1)) == 0;
}

/// exp(sign·2πi·k/n) for k < n/2, each computed directly (not by repeated multiplication) to
/// keep the error at ~1 ulp.
std::vector<Complex> twiddles(std::size_t n, int sign) {
  std::vector<Complex> t(n / 2);
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double angle = double(sign) * 2.0 * kPi * double(k) / double(n);
    t[k] = Complex(std::cos(angle), std::sin(angle));
  }
  return t;
}

/// Iterative radix-2 transform of a power-of-two length n with `twiddle` = twiddles(n, sign):
/// sign −1 forward, +1 inverse (unnormalised).
void radix2(std::vector<Complex>& a, const std::vector<Complex>& twiddle) {
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
    const std::size_t half = len / 2, stride = n / len;
    for (std::size_t start = 0; start < n; start += len)
      for (std::size_t k = 0; k < half; ++k) {
        const Complex u = a[start + k];
        const Complex v = a[start + k + half] * twiddle[k * stride];
        a[start + k] = u + v;
        a[start + k + half] = u - v;
      }
  }
}

/// What a transform of one length needs, computed once and applied to many lines.
class Plan {
public:
  explicit Plan(std::size_t n) : n_(n) {
    if (n_ <= 1)
      return;
    if (isPowerOfTwo(n_)) {
      forward_ = twiddles(n_, -1);
      return;
    }
    // Bluestein: X[k] = conj(w[k]) · Σ_j (x[j]·conj(w[j])) · w[k−j] with w[m] = exp(iπm²/n),
    // the convolution done by power-of-two transforms of length m ≥ 2n − 1.
    m_ = 1;
    while (m_ < 2 * n_ - 1)
      m_ <<= 1;
    forward_ = twiddles(m_, -1);
    inverse_ = twiddles(m_, +1);
    chirp_.resize(n_);
    for (std::size_t k = 0; k < n_; ++k) {
      const std::size_t k2 = (k * k) % (2 * n_); // keeps the angle small and exact
      const double angle = kPi * double(k2) / double(n_);
      chirp_[k] = Complex(std::cos(angle), std::sin(angle));
    }
    kernel_.assign(m_, Complex());
    kernel_[0] = chirp_[0];
    for (std::size_t k = 1; k < n_; ++k)
      kernel_[k] = kernel_[m_ - k] = chirp_[k];
    radix2(kernel_, forward_);
    work_.resize(m_);
  }

  /// Transforms `x` (of the plan's length) in place.
  void apply(std::vector<Complex>& x) {
    if (n_ <= 1)
      return;
    if (m_ == 0) {
      radix2(x, forward_);
      return;
    }
    std::fill(work_.begin(), work_.end(), Complex());
    for (std::size_t k = 0; k < n_; ++k)
      work_[k] = x[k] * std::conj(chirp_[k]);
    radix2(work_, forward_);
    for (std::size_t k = 0; k < m_; ++k)
      work_[k] *= kernel_[k];
    radix2(work_, inverse_);
    for (std::size_t k = 0; k < n_; ++k)
      x[k] = work_[k] * std::conj(chirp_[k]) / double(m_);
  }

private:
  std::size_t n_;
  std::size_t m_ = 0; ///< Bluestein's power-of-two length; 0 for a radix-2 plan.
  std::vector<Complex> forward_, inverse_, chirp_, kernel_, work_;
};

} // namespace

void fft(std::vector<Complex>& values) {
  Plan(values.size()).apply(values);
}

void fft2(std::vector<Complex>& values, int width, int height) {
  STRAHLER_ASSERT(width >= 0 && height >= 0 &&
                      values.size() == std::size_t(width) * std::size_t(height),
                  "fft2: size mismatch");
  const std::size_t w = std::size_t(width), h = std::size_t(height);
  Plan rows(w), columns(h);
  std::vector<Complex> line(w);
  for (std::size_t y = 0; y < h; ++y) {
    std::copy(values.begin() + std::ptrdiff_t(y * w), values.begin() + std::ptrdiff_t(y * w + w),
              line.begin());
    rows.apply(line);
    std::copy(line.begin(), line.end(), values.begin() + std::ptrdiff_t(y * w));
  }
  line.resize(h);
  for (std::size_t x = 0; x < w; ++x) {
    for (std::size_t y = 0; y < h; ++y)
      line[y] = values[y * w + x];
    columns.apply(line);
    for (std::size_t y = 0; y < h; ++y)
      values[y * w + x] = line[y];
  }
}

} // namespace strahler::quality
