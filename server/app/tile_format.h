#pragma once
// The tile vocabulary of URLs and the command line, apart from the service that renders tiles,
// so that parsing a request needs none of the terrain code (the fuzz harnesses build it alone).

#include "strahler/base/result.h"
#include "strahler/tiling/tile_scheme.h"

#include <string>

namespace strahler::app {

/// Every tile format strahler serves.
enum class TileFormat { kTerrainRgb, kTerrarium, kPng16, kTiff, kExr, kDraco, kGlb };

/// Size bounds: raster tiles have size² pixels, mesh tiles size² quads ((size+1)² vertices).
struct TileSizes {
  static constexpr int kRasterMin = 16, kRasterMax = 1024, kRasterDefault = 256;
  static constexpr int kMeshMin = 4, kMeshMax = 256, kMeshDefault = 64;
};

/// One tile to make.
struct TileRequest {
  tiling::SchemeKind scheme = tiling::SchemeKind::kWebMercator;
  tiling::TileId tile;
  TileFormat format = TileFormat::kTerrainRgb;
  int size = 0; ///< 0: the format's default.
};

/// Parses a format name as used in URLs and on the command line: png (Terrain-RGB),
/// terrarium, png16, tif, exr, drc, glb.
base::Result<TileFormat> parseTileFormat(const std::string& name);

/// True for the mesh formats (drc, glb).
bool isMeshFormat(TileFormat format) noexcept;

} // namespace strahler::app
