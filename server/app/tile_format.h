#pragma once
// The tile vocabulary of URLs and the command line, apart from the service that renders tiles,
// so that parsing a request needs none of the terrain code (the fuzz harnesses build it alone).

#include "strahler/base/result.h"

#include <string>

namespace strahler::app {

/// Every tile format strahler serves.
enum class TileFormat {
  kTerrainRgb,
  kTerrarium,
  kPng16,
  kTiff,
  kExr,
  kDraco,
  kGlb,
  kRelief,         ///< A colour-relief picture (relief).
  kQuantizedMesh,  ///< Cesium's quantized-mesh-1.0 (.terrain), geographic pyramid only.
  kMvt,            ///< A Mapbox Vector Tile 2.1 (.mvt), Web Mercator pyramid only.
  kLayerPng,       ///< A derived layer (layers/{name}/...png): 8- or 16-bit grey PNG.
  kVegetationJson, ///< Vegetation instances (vegetation/...json), Web Mercator pyramid only.
};

/// The kind of data a tile carries; each kind has one renderer (tile_renderer.h), and a
/// format is one encoding of one kind.
enum class TileKind {
  kHeightmap,  ///< A raster of heights (png, terrarium, png16, tif, exr).
  kMesh,       ///< A triangle mesh with skirts (drc, glb).
  kRelief,     ///< A colour-relief picture: hypsometric tint × hillshade (relief).
  kTerrain,    ///< A Cesium terrain tile: adaptive mesh, normals, water mask, availability.
  kVector,     ///< A vector tile: rivers, contours, water, the artist's map (mvt).
  kLayer,      ///< A derived layer of the terrain (slope, sky view, water, ...): LayerName.
  kVegetation, ///< Trees and bushes placed on the terrain (json).
};

/// The derived layers (docs/architecture.md, "Layer tiles"), as named in URLs.
enum class LayerName {
  kSlope,        ///< "slope": degrees, 16-bit grey (value = degrees · 100).
  kAspect,       ///< "aspect": degrees from north, 16-bit grey (· 100; 65535 flat).
  kIllumination, ///< "illumination": the seed's sky view, 8-bit grey (· 255).
  kHillshade,    ///< "hillshade": Lambert under ?azimuth=&altitude=, 8-bit grey (· 255).
  kHumidity,     ///< "humidity": 0 … 1, 8-bit grey (· 255).
  kSediment,     ///< "sediment": thickness, 8-bit grey (centimetres).
  kVegetation,   ///< "vegetation": density of ?species=, 8-bit grey (· 255).
  kWater,        ///< "water": sea, lakes and rivers 255, land 0, 8-bit grey.
};

/// Every layer name, in LayerName order.
inline constexpr const char* kLayerNames[] = {"slope",    "aspect",   "illumination", "hillshade",
                                              "humidity", "sediment", "vegetation",   "water"};

/// What a layer tile asks for beyond its zoom, position and size, in canonical form.
struct LayerOptions {
  LayerName name = LayerName::kSlope; ///< The layer.
  int species = 0;                    ///< kVegetation: index in layers::kSpecies; else 0.
  double azimuthDeg = 0.0;            ///< kHillshade: sun azimuth (0 … 360); else 0.
  double altitudeDeg = 0.0;           ///< kHillshade: sun altitude (0 … 90); else 0.

  friend bool operator==(const LayerOptions&, const LayerOptions&) = default;
};

/// The layer named `name`, or kNotFound naming the layers there are.
base::Result<LayerName> parseLayerName(const std::string& name);

/// Size bounds: raster tiles have size² pixels, mesh tiles size² quads ((size+1)² vertices).
struct TileSizes {
  static constexpr int kRasterMin = 16, kRasterMax = 1024, kRasterDefault = 256;
  static constexpr int kMeshMin = 4, kMeshMax = 256, kMeshDefault = 64;
  /// Quads per side of the grid a Cesium terrain tile is meshed from (65 samples, Cesium's).
  static constexpr int kTerrainGrid = 64;
};

/// The sizes one kind of tile accepts, and the one it gets when none is asked for.
struct TileSizeRange {
  int min = 0;         ///< Smallest size.
  int max = 0;         ///< Largest size.
  int defaultSize = 0; ///< The size of a request that names none.
};

/// Parses a format name as used in URLs and on the command line: png (Terrain-RGB),
/// terrarium, png16, tif, exr, drc, glb, relief (colour relief), terrain (quantized-mesh),
/// mvt (vector tile), json (vegetation instances).
base::Result<TileFormat> parseTileFormat(const std::string& name);

/// The name of `format` in URLs (png, terrarium, png16, tif, exr, drc, glb, relief, terrain,
/// mvt; "layer" for layer tiles, which are .png under layers/{name}/; "json" for vegetation).
const char* canonicalFormatName(TileFormat format) noexcept;

/// The kind of tile `format` encodes.
TileKind tileKind(TileFormat format) noexcept;

/// True for the mesh formats (drc, glb).
bool isMeshFormat(TileFormat format) noexcept;

/// The sizes tiles of `kind` accept (TileSizes).
TileSizeRange tileSizeRange(TileKind kind) noexcept;

} // namespace strahler::app
