#pragma once

#include "strahler/base/result.h"
#include "strahler/construction/world.h"
#include "strahler/tiling/tile_evaluator.h"
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

/// A finished tile with what it cost.
struct RenderedTile {
  std::string bytes;
  std::string mimeType;
  double evaluateMs = 0.0;
  double encodeMs = 0.0;
  tiling::TileStats stats;
};

/// Largest position error (m) a mesh tile's Draco quantisation may introduce: 1 cm, or a
/// thousandth of the vertex spacing on coarse tiles (kilometre-wide tiles cannot keep 1 cm in
/// float32 coordinates).
double meshPositionError(double vertexSpacing) noexcept;

/// Parses a format name as used in URLs and on the command line: png (Terrain-RGB),
/// terrarium, png16, tif, exr, drc, glb.
base::Result<TileFormat> parseTileFormat(const std::string& name);

/// True for the mesh formats (drc, glb).
bool isMeshFormat(TileFormat format) noexcept;

/// Makes tiles of one world: both pyramids, every format. Thread-safe.
class TileService {
public:
  /// A service over `world` (kept by the service).
  explicit TileService(construction::WorldData world);
  TileService(const TileService&) = delete;
  TileService& operator=(const TileService&) = delete;

  /// The tile, or kNotFound when it is outside the pyramid, kOutOfRange for a bad size.
  base::Result<RenderedTile> render(const TileRequest& request) const;

  /// The evaluated world.
  const construction::World& world() const noexcept { return world_; }
  /// The pyramid of `kind`.
  const tiling::TileScheme& scheme(tiling::SchemeKind kind) const noexcept {
    return kind == tiling::SchemeKind::kLocal ? local_ : web_;
  }

private:
  construction::World world_;
  tiling::TileEvaluator evaluator_;
  tiling::TileScheme web_;
  tiling::TileScheme local_;
};

} // namespace strahler::app
