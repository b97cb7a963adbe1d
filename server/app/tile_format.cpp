#include "tile_format.h"

#include <iterator>

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
  if (name == "terrain")
    return TileFormat::kQuantizedMesh;
  if (name == "relief")
    return TileFormat::kRelief;
  if (name == "mvt")
    return TileFormat::kMvt;
  if (name == "json")
    return TileFormat::kVegetationJson;
  return base::makeError(
      base::ErrorCode::kInvalidInput,
      "unknown tile format '" + name +
          "' (use png, terrarium, png16, tif, exr, drc, glb, relief, terrain, mvt or json)");
}

base::Result<LayerName> parseLayerName(const std::string& name) {
  for (std::size_t i = 0; i < std::size(kLayerNames); ++i)
    if (name == kLayerNames[i])
      return static_cast<LayerName>(i);
  std::string known;
  for (const char* n : kLayerNames)
    known += (known.empty() ? "" : ", ") + std::string(n);
  return base::makeError(base::ErrorCode::kNotFound,
                         "unknown layer '" + name.substr(0, 64) + "' (layers: " + known + ")");
}

const char* canonicalFormatName(TileFormat format) noexcept {
  switch (format) {
  case TileFormat::kTerrainRgb:
    return "png";
  case TileFormat::kTerrarium:
    return "terrarium";
  case TileFormat::kPng16:
    return "png16";
  case TileFormat::kTiff:
    return "tif";
  case TileFormat::kExr:
    return "exr";
  case TileFormat::kDraco:
    return "drc";
  case TileFormat::kGlb:
    return "glb";
  case TileFormat::kQuantizedMesh:
    return "terrain";
  case TileFormat::kRelief:
    return "relief";
  case TileFormat::kMvt:
    return "mvt";
  case TileFormat::kLayerPng:
    return "layer";
  case TileFormat::kVegetationJson:
    return "json";
  }
  return "png";
}

TileKind tileKind(TileFormat format) noexcept {
  if (format == TileFormat::kQuantizedMesh)
    return TileKind::kTerrain;
  if (format == TileFormat::kRelief)
    return TileKind::kRelief;
  if (format == TileFormat::kMvt)
    return TileKind::kVector;
  if (format == TileFormat::kLayerPng)
    return TileKind::kLayer;
  if (format == TileFormat::kVegetationJson)
    return TileKind::kVegetation;
  return format == TileFormat::kDraco || format == TileFormat::kGlb ? TileKind::kMesh
                                                                    : TileKind::kHeightmap;
}

bool isMeshFormat(TileFormat format) noexcept {
  return tileKind(format) == TileKind::kMesh;
}

TileSizeRange tileSizeRange(TileKind kind) noexcept {
  if (kind == TileKind::kMesh)
    return {TileSizes::kMeshMin, TileSizes::kMeshMax, TileSizes::kMeshDefault};
  if (kind == TileKind::kTerrain)
    return {TileSizes::kTerrainGrid, TileSizes::kTerrainGrid, TileSizes::kTerrainGrid};
  if (kind == TileKind::kVector ||
      kind == TileKind::kVegetation) // one size: the contours' grid (vector_layers.h)
    return {TileSizes::kRasterDefault, TileSizes::kRasterDefault, TileSizes::kRasterDefault};
  return {TileSizes::kRasterMin, TileSizes::kRasterMax, TileSizes::kRasterDefault};
}

} // namespace strahler::app
