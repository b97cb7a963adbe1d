#pragma once

#include "tile_renderer.h"
#include "tile_request.h"
#include "tile_status.h"

#include "strahler/base/result.h"
#include "strahler/construction/world.h"
#include "strahler/tiling/tile_evaluator.h"
#include "strahler/tiling/tile_scheme.h"

#include <array>
#include <memory>
#include <utility>

namespace strahler::app {

/// What a render error means to whoever asked: kNotFound for a tile outside its pyramid,
/// kUnsupported for a format this installation cannot make (its OpenImageIO module is
/// missing), kFailed for the rest.
service::TileStatus renderStatus(base::ErrorCode code) noexcept;

/// A request that TileService::checkTile() has passed, and only it makes one: a tile checked
/// on its way in is not checked again on its way to a renderer.
class CheckedTile {
public:
  /// The request, in its pyramid and of a kind that pyramid serves.
  const TileRequest& request() const noexcept { return request_; }

private:
  friend class TileService;
  explicit CheckedTile(TileRequest request) : request_(std::move(request)) {}
  TileRequest request_;
};

/// Makes tiles of one world: both pyramids, every kind of tile, each kind by its renderer.
/// Knows nothing of the transport (the server, `strahler tile` and `strahler export` share it).
/// Thread-safe.
class TileService {
public:
  /// A service over `world` (kept by the service).
  explicit TileService(construction::WorldData world);
  ~TileService();
  TileService(const TileService&) = delete;
  TileService& operator=(const TileService&) = delete;

  /// `request` as a CheckedTile, or kNotFound when its tile is outside its pyramid (the
  /// message says which zooms it has), kInvalidInput for a kind its pyramid does not serve
  /// (Cesium terrain is only, and only, in the geographic one; layer tiles are not in it);
  /// cheap, so a server can refuse such a tile before queueing it.
  base::Result<CheckedTile> checkTile(const TileRequest& request) const;
  /// The tile of a checked request, or kOutOfRange for a bad size, or the renderer's error
  /// (renderStatus() says what each means).
  base::Result<RenderedTile> render(const CheckedTile& tile) const;
  /// checkTile(), then render(): for callers that check nothing before (`strahler tile`,
  /// `strahler export`).
  base::Result<RenderedTile> render(const TileRequest& request) const;

  /// The evaluated world.
  const construction::World& world() const noexcept { return world_; }
  /// The pyramid of `kind`.
  const tiling::TileScheme& scheme(tiling::SchemeKind kind) const noexcept {
    switch (kind) {
    case tiling::SchemeKind::kLocal:
      return local_;
    case tiling::SchemeKind::kGeographic:
      return geographic_;
    case tiling::SchemeKind::kWebMercator:
      break;
    }
    return web_;
  }

private:
  construction::World world_;
  tiling::TileEvaluator evaluator_;
  tiling::TileScheme web_;
  tiling::TileScheme local_;
  tiling::TileScheme geographic_;
  /// The renderer of each TileKind, by its value.
  std::array<std::unique_ptr<const TileRenderer>,
             static_cast<std::size_t>(TileKind::kVegetation) + 1>
      renderers_;
};

} // namespace strahler::app
