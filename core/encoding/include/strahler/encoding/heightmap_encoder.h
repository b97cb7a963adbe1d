#pragma once

#include "strahler/base/result.h"
#include "strahler/encoding/height_grid.h"

#include <string>

namespace strahler::encoding {

/// Raster heightmap formats served as tiles.
enum class HeightmapFormat {
  kTerrainRgb, ///< Mapbox Terrain-RGB PNG: h = −10000 + (R·65536 + G·256 + B) · 0.1.
  kTerrarium,  ///< Terrarium PNG: h = R·256 + G + B/256 − 32768.
  kPng16,      ///< 16-bit grey PNG: h = value · 0.1 − 1000 (range −1000 … 5553.5 m).
  kTiff,       ///< Single-channel float32 TIFF, metres.
  kExr,        ///< Single-channel float32 OpenEXR, metres.
};

/// Encodes `grid` in `format`; heights outside a format's range are clamped to it (Terrain-RGB
/// −10000 … 1667721.5 m, Terrarium −32768 … 32767.996 m, png16 as above). PNGs are 8-bit RGB
/// or 16-bit grey with no ancillary chunks; TIFF is deflate-compressed, EXR ZIP-compressed.
/// kInvalidInput when width or height is outside 1 … 4096, heights.size() ≠ width·height, or a
/// height is NaN or infinite (the message names the pixel); kInternal when a codec fails.
/// Deterministic: the same grid gives the same bytes.
base::Result<std::string> encodeHeightmap(const HeightGrid& grid, HeightmapFormat format);

/// MIME type of a format ("image/png", "image/tiff", "image/x-exr").
const char* mimeType(HeightmapFormat format) noexcept;

} // namespace strahler::encoding
