#pragma once

#include "tile_format.h"

#include "strahler/tiling/tile_scheme.h"

#include <string>

namespace strahler::app {

/// What a tile request may tune beyond its format; the same for every transport.
struct TileOptions {
  int size = 0; ///< Pixels or quads per side; 0: the kind's default (tileSizeRange()).
  /// Cesium terrain only: the extensions asked for (CesiumExtension bits).
  unsigned extensions = 0;
  /// Cesium terrain, vector and vegetation tiles only: the bytes gzipped (sent as Content-Encoding:
  /// gzip).
  bool gzip = false;
  /// Layer tiles only: the layer and its parameters.
  LayerOptions layer = {};
};

/// The quantized-mesh extensions a Cesium client may ask for, as TileOptions::extensions bits.
enum CesiumExtension : unsigned {
  kOctVertexNormals = 1u, ///< "octvertexnormals"
  kWaterMask = 2u,        ///< "watermask"
  kMetadata = 4u,         ///< "metadata"
};

/// One tile to make, whoever asks (a URL, `strahler tile`, `strahler export`): a plain value
/// that knows nothing of the transport.
struct TileRequest {
  tiling::SchemeKind scheme = tiling::SchemeKind::kWebMercator; ///< The pyramid.
  geometry::TileId tile;                                        ///< z/x/y in that pyramid.
  TileFormat format = TileFormat::kTerrainRgb;                  ///< Its kind and encoding.
  TileOptions options; ///< Canonical: size 0 for the default.
  std::string world;   ///< Id of the world; "" where one service serves one world.

  /// The kind of tile asked for (from its format).
  TileKind kind() const noexcept { return tileKind(format); }
};

/// The canonical key of `request`: "world|tiles|z|x|y|format|size" ("local" for the local
/// pyramid, "cesium" for the geographic one, the format's canonical name, size 0 for the
/// default; Cesium terrain adds "|extensions|gzip", vector and vegetation tiles "|gz" or "|id", a
/// layer tile
/// "|name" and its species or "|azimuth|altitude"). Requests for the same tile have the same key as
/// long as their size is 0 whenever it is the default (parseTileRoute
/// makes it so): the tile's cache key and, with its world's cache key, its ETag.
std::string tileKey(const TileRequest& request);

} // namespace strahler::app
