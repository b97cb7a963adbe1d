#pragma once
// The coarse step the costly layers share (sky view, the rivers' wetness): values at every
// other pixel of every other row, the last row and column in the border, interpolated.

#include <cstddef>
#include <vector>

namespace strahler::layers::detail {

/// A width × height raster (both even) from `coarse` values at its even pixels, (width / 2 + 1)
/// per row, height / 2 + 1 rows: bilinear between them (the last ones are the next tile's
/// first pixels, so that tiles agree).
inline std::vector<double> upsampleEven(const std::vector<double>& coarse, std::size_t width,
                                        std::size_t height) {
  const std::size_t cw = width / 2 + 1;
  std::vector<double> out(width * height);
  for (std::size_t y = 0; y < height; ++y) {
    const double ty = y % 2 == 1 ? 0.5 : 0.0;
    for (std::size_t x = 0; x < width; ++x) {
      const double tx = x % 2 == 1 ? 0.5 : 0.0;
      const double* a = &coarse[y / 2 * cw + x / 2];
      const double top = a[0] + tx * (a[1] - a[0]);
      const double bottom = a[cw] + tx * (a[cw + 1] - a[cw]);
      out[y * width + x] = ty == 0.0 ? top : top + ty * (bottom - top);
    }
  }
  return out;
}

} // namespace strahler::layers::detail
