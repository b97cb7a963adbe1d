#pragma once

#include <cstdint>

namespace strahler::geometry {

/// The row of a tile of zoom z counted from the other pole: 2^z − 1 − row, z in [0, 62]. XYZ
/// rows count from the north, TMS rows (Cesium's terrain URLs, MBTiles) from the south; the
/// flip turns either into the other.
constexpr std::int64_t flipRow(int z, std::int64_t row) noexcept {
  return (std::int64_t{1} << z) - 1 - row;
}

} // namespace strahler::geometry
