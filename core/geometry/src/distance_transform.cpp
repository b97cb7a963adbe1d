#include "strahler/geometry/distance_transform.h"

#include "strahler/base/assert.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace strahler::geometry {
namespace {

/// Squared distances (in cells²) of one line `f` to its nearest zero, in place
/// (Felzenszwalb & Huttenlocher 2012, lower envelope of parabolas).
void transformLine(std::vector<double>& f, std::vector<int>& v, std::vector<double>& z,
                   std::vector<double>& d) {
  const int n = int(f.size());
  constexpr double kInf = std::numeric_limits<double>::infinity();
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (!std::isfinite(f[std::size_t(q)]))
      continue;
    while (k >= 0) {
      const int p = v[std::size_t(k)];
      const double s = ((f[std::size_t(q)] + double(q) * q) - (f[std::size_t(p)] + double(p) * p)) /
                       (2.0 * (q - p));
      if (s > z[std::size_t(k)])
        break;
      --k;
    }
    ++k;
    v[std::size_t(k)] = q;
    z[std::size_t(k)] = k == 0 ? -kInf
                               : ((f[std::size_t(q)] + double(q) * q) -
                                  (f[std::size_t(v[std::size_t(k - 1)])] +
                                   double(v[std::size_t(k - 1)]) * v[std::size_t(k - 1)])) /
                                     (2.0 * (q - v[std::size_t(k - 1)]));
  }
  if (k < 0)
    return; // nothing finite on this line
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (j < k && z[std::size_t(j + 1)] < q)
      ++j;
    const int p = v[std::size_t(j)];
    d[std::size_t(q)] = double(q - p) * double(q - p) + f[std::size_t(p)];
  }
  for (int q = 0; q < n; ++q)
    f[std::size_t(q)] = d[std::size_t(q)];
}

} // namespace

std::vector<float> distanceToMarked(int width, int height, double cellSize,
                                    const std::vector<std::uint8_t>& marked) {
  const std::size_t w = std::size_t(width), h = std::size_t(height);
  STRAHLER_ASSERT(marked.size() == w * h, "mask does not match width * height");
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<float> out(w * h);
  const std::size_t longest = std::max(w, h);
  std::vector<double> f(longest), d(longest), z(longest + 1);
  std::vector<int> v(longest);
  std::vector<double> columns(w * h);
  for (std::size_t x = 0; x < w; ++x) {
    f.resize(h), d.resize(h);
    for (std::size_t y = 0; y < h; ++y)
      f[y] = marked[y * w + x] != 0 ? 0.0 : kInf;
    transformLine(f, v, z, d);
    for (std::size_t y = 0; y < h; ++y)
      columns[y * w + x] = f[y];
  }
  for (std::size_t y = 0; y < h; ++y) {
    f.assign(columns.begin() + std::ptrdiff_t(y * w), columns.begin() + std::ptrdiff_t(y * w + w));
    d.resize(w);
    transformLine(f, v, z, d);
    for (std::size_t x = 0; x < w; ++x)
      out[y * w + x] = float(std::sqrt(f[x]) * cellSize);
  }
  return out;
}

} // namespace strahler::geometry
