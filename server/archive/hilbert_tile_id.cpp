#include "hilbert_tile_id.h"

#include <cassert>
#include <utility>

namespace strahler::archive {
namespace {

/// Tiles of all zooms below z: (4^z − 1) / 3.
std::uint64_t tilesBelow(int z) noexcept {
  return ((std::uint64_t{1} << (2 * z)) - 1) / 3;
}

/// The Hilbert curve's quadrant rotation (spec reference implementation).
void rotate(std::uint64_t n, std::uint64_t& x, std::uint64_t& y, std::uint64_t rx,
            std::uint64_t ry) noexcept {
  if (ry == 0) {
    if (rx == 1) {
      x = n - 1 - x;
      y = n - 1 - y;
    }
    std::swap(x, y);
  }
}

} // namespace

std::uint64_t zxyToTileId(TileCoord tile) noexcept {
  assert(tile.z >= 0 && tile.z <= kMaxHilbertZoom);
  const std::uint64_t n = std::uint64_t{1} << tile.z;
  std::uint64_t x = tile.x, y = tile.y, d = 0;
  for (std::uint64_t s = n / 2; s > 0; s /= 2) {
    const std::uint64_t rx = (x & s) > 0 ? 1 : 0;
    const std::uint64_t ry = (y & s) > 0 ? 1 : 0;
    d += s * s * ((3 * rx) ^ ry);
    rotate(s, x, y, rx, ry);
  }
  return tilesBelow(tile.z) + d;
}

TileCoord tileIdToZxy(std::uint64_t id) noexcept {
  int z = 0;
  while (z < kMaxHilbertZoom && tilesBelow(z + 1) <= id)
    ++z;
  const std::uint64_t n = std::uint64_t{1} << z;
  std::uint64_t t = id - tilesBelow(z), x = 0, y = 0;
  for (std::uint64_t s = 1; s < n; s *= 2) {
    const std::uint64_t rx = 1 & (t / 2);
    const std::uint64_t ry = 1 & (t ^ rx);
    rotate(s, x, y, rx, ry);
    x += s * rx;
    y += s * ry;
    t /= 4;
  }
  return {z, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)};
}

} // namespace strahler::archive
