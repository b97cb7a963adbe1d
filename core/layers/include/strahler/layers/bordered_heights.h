#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace strahler::layers {

/// Slope of the ground at a pixel, m per m: `dzdx` rising east, `dzdy` rising north.
struct Gradient {
  double dzdx = 0.0; ///< East component.
  double dzdy = 0.0; ///< North component.
};

/// A `width` × `height` raster of heights with a border of `border` ≥ 1 samples on every side
/// (TileScheme::borderedRasterGrid): `heights` holds (width + 2·border) · (height + 2·border)
/// values, row-major, row 0 north; `rowSpacing` one ground distance between neighbouring
/// samples per bordered row, m. Pixel coordinates run from −border to width + border − 1.
/// Every layer is a function of these samples only, so a tile cut out of a larger raster with
/// its neighbours' samples as border gives the larger raster's values exactly (seamless tiles).
struct BorderedHeights {
  std::span<const double> heights;    ///< The bordered samples, m.
  int width = 0;                      ///< Pixels per row inside the border.
  int height = 0;                     ///< Rows inside the border.
  int border = 1;                     ///< Samples of border on each side.
  std::span<const double> rowSpacing; ///< Per bordered row, m.

  /// The height at pixel (x, y); x, y may reach `border` samples outside the raster.
  double at(int x, int y) const noexcept {
    return heights[static_cast<std::size_t>(y + border) * stride() +
                   static_cast<std::size_t>(x + border)];
  }
  /// The sample spacing of pixel row y, m.
  double spacing(int y) const noexcept { return rowSpacing[static_cast<std::size_t>(y + border)]; }
  /// Samples per bordered row.
  std::size_t stride() const noexcept { return static_cast<std::size_t>(width + 2 * border); }
  /// Asserts that the spans hold what the sizes say.
  void check() const;
};

/// The slope at pixel (x, y): central differences of its four neighbours (as the relief
/// tiles' hillshade takes it).
Gradient gradientAt(const BorderedHeights& grid, int x, int y) noexcept;

/// tan of the slope angle: the gradient's length, m per m.
inline double tanSlope(Gradient g) noexcept {
  return std::sqrt(g.dzdx * g.dzdx + g.dzdy * g.dzdy);
}

/// (mean of the four neighbours − h) / spacing at pixel (x, y), m per m: > 0 in hollows and
/// valleys (where sediment and water collect), < 0 on crests.
double concavityAt(const BorderedHeights& grid, int x, int y) noexcept;

/// `value(x, y)` for every pixel inside the border, row-major, row 0 north (after check()).
template <class PixelValue>
std::vector<double> perPixel(const BorderedHeights& grid, PixelValue value) {
  grid.check();
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height));
  for (int y = 0; y < grid.height; ++y)
    for (int x = 0; x < grid.width; ++x)
      out.push_back(value(x, y));
  return out;
}

} // namespace strahler::layers
