#pragma once

#include "strahler/tiling/tile_scheme.h"

#include <cmath>
#include <cstdint>

namespace strahler::test_support {

/// The Web Mercator (XYZ) tile at zoom z that holds (lon, lat), in degrees. Header-only: only
/// tests that link the tiling library include it.
inline geometry::TileId webTileAt(double lon, double lat, int z) {
  const double n = std::ldexp(1.0, z);
  const double latRad = lat * M_PI / 180.0;
  return {z, static_cast<std::int64_t>((lon + 180.0) / 360.0 * n),
          static_cast<std::int64_t>((1.0 - std::asinh(std::tan(latRad)) / M_PI) / 2.0 * n)};
}

} // namespace strahler::test_support
