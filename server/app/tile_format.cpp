#include "tile_format.h"

namespace strahler::app {

base::Result<TileFormat> parseTileFormat(const std::string& name) {
  if (name == "png")
    return TileFormat::kTerrainRgb;
  if (name == "terrarium")
    return TileFormat::kTerrarium;
  if (name == "png16")
    return TileFormat::kPng16;
  if (name == "tif" || name == "tiff")
    return TileFormat::kTiff;
  if (name == "exr")
    return TileFormat::kExr;
  if (name == "drc")
    return TileFormat::kDraco;
  if (name == "glb")
    return TileFormat::kGlb;
  return base::makeError(base::ErrorCode::kInvalidInput,
                         "unknown tile format '" + name +
                             "' (use png, terrarium, png16, tif, exr, drc or glb)");
}

bool isMeshFormat(TileFormat format) noexcept {
  return format == TileFormat::kDraco || format == TileFormat::kGlb;
}

} // namespace strahler::app
