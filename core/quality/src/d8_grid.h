#pragma once

// The D8 neighbourhood of a HeightRaster's cells, shared by the drainage check and the flow
// field (internal to core/quality).

#include "strahler/quality/drainage.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace strahler::quality::d8 {

/// A cell's index, y * width + x.
using Cell = std::uint32_t;

/// Offsets of the 8 neighbours, counter-clockwise from east.
inline constexpr std::array<int, 8> kDx = {1, 1, 0, -1, -1, -1, 0, 1};
inline constexpr std::array<int, 8> kDy = {0, 1, 1, 1, 0, -1, -1, -1};
/// Distance to a diagonal neighbour, in cells.
inline constexpr double kDiagonal = 1.4142135623730951;

/// Whether cell i of `raster` is land.
inline bool isLand(const HeightRaster& raster, std::size_t i) noexcept {
  return raster.cellClass[i] == std::uint8_t(CellClass::kLand) ||
         raster.cellClass[i] == std::uint8_t(CellClass::kShore);
}

/// Calls fn(neighbour, k) for each of the 8 neighbours of c inside a width × height raster
/// (k indexes kDx, kDy).
template <class Fn> void forEachNeighbour(int width, int height, Cell c, Fn&& fn) {
  const int x = int(c % Cell(width)), y = int(c / Cell(width));
  for (std::size_t k = 0; k < 8; ++k) {
    const int nx = x + kDx[k], ny = y + kDy[k];
    if (nx >= 0 && ny >= 0 && nx < width && ny < height)
      fn(Cell(ny) * Cell(width) + Cell(nx), k);
  }
}

/// True if c is on the raster's border or has a water neighbour: its water leaves.
inline bool touchesSink(const HeightRaster& raster, Cell c) {
  const int x = int(c % Cell(raster.width)), y = int(c / Cell(raster.width));
  if (x == 0 || y == 0 || x == raster.width - 1 || y == raster.height - 1)
    return true;
  if (raster.cellClass[c] == std::uint8_t(CellClass::kShore))
    return true;
  bool sink = false;
  forEachNeighbour(raster.width, raster.height, c,
                   [&](Cell n, std::size_t) { sink = sink || !isLand(raster, n); });
  return sink;
}

} // namespace strahler::quality::d8
