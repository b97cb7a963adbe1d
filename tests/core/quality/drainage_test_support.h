#pragma once

#include "strahler/quality/drainage.h"

#include <cmath>
#include <cstddef>

namespace strahler::quality::test {

/// An all-land raster of w x h cells of `cellSize` metres with heights z(x, y).
template <class HeightFn> HeightRaster landRaster(int w, int h, double cellSize, HeightFn&& z) {
  HeightRaster raster;
  raster.width = w;
  raster.height = h;
  raster.cellSize = cellSize;
  const std::size_t n = std::size_t(w) * std::size_t(h);
  raster.heights.resize(n);
  raster.cellClass.assign(n, std::uint8_t(CellClass::kLand));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      raster.heights[std::size_t(y * w + x)] = float(z(x, y));
  return raster;
}

/// Index of cell (x, y).
inline std::size_t at(const HeightRaster& raster, int x, int y) {
  return std::size_t(y * raster.width + x);
}

/// Sets cell (x, y) to `cls`.
inline void setClass(HeightRaster& raster, int x, int y, CellClass cls) {
  raster.cellClass[at(raster, x, y)] = std::uint8_t(cls);
}

/// Number of land cells (shore cells included).
inline std::size_t countLand(const HeightRaster& raster) {
  std::size_t land = 0;
  for (std::uint8_t c : raster.cellClass)
    land += c == std::uint8_t(CellClass::kLand) || c == std::uint8_t(CellClass::kShore) ? 1 : 0;
  return land;
}

} // namespace strahler::quality::test
