#pragma once

#include <cstdint>

namespace strahler::geometry {

/// A quadtree tile: zoom z, column x (west to east), row y (north to south, as in XYZ). The
/// one tile id of the tile schemes, the vegetation tiles and the server.
struct TileId {
  int z = 0;
  std::int64_t x = 0;
  std::int64_t y = 0;

  friend bool operator==(const TileId&, const TileId&) = default;
};

/// The row of a tile of zoom z counted from the other pole: 2^z − 1 − row, z in [0, 62]. XYZ
/// rows count from the north, TMS rows (Cesium's terrain URLs, MBTiles) from the south; the
/// flip turns either into the other.
constexpr std::int64_t flipRow(int z, std::int64_t row) noexcept {
  return (std::int64_t{1} << z) - 1 - row;
}

} // namespace strahler::geometry
