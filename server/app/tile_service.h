#pragma once

#include "tile_format.h"

#include "strahler/base/result.h"
#include "strahler/construction/world.h"
#include "strahler/tiling/tile_evaluator.h"
#include "strahler/tiling/tile_scheme.h"

#include <string>

namespace strahler::app {

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
