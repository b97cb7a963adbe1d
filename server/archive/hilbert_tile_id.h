#pragma once

#include "tile_archive.h"

#include <cstdint>

namespace strahler::archive {

/// Deepest zoom whose tile ids fit in 64 bits (PMTiles v3 allows z ≤ 31).
inline constexpr int kMaxHilbertZoom = 31;

/// The PMTiles v3 tile id of a tile: the number of tiles of all lower zooms plus the tile's
/// position along the zoom's Hilbert curve (z0 → 0, z1 0/0 → 1, 0/1 → 2, 1/1 → 3, 1/0 → 4).
std::uint64_t zxyToTileId(TileCoord tile) noexcept;

/// The tile of a PMTiles v3 tile id (the inverse of zxyToTileId).
TileCoord tileIdToZxy(std::uint64_t id) noexcept;

} // namespace strahler::archive
