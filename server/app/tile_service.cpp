#include "tile_service.h"

#include "cesium_terrain_renderer.h"
#include "heightmap_renderer.h"
#include "layer_renderer.h"
#include "mesh_renderer.h"
#include "relief_renderer.h"
#include "vector_tile_renderer.h"
#include "vegetation_renderer.h"

#include <string>

namespace strahler::app {

service::TileStatus renderStatus(base::ErrorCode code) noexcept {
  switch (code) {
  case base::ErrorCode::kNotFound:
    return service::TileStatus::kNotFound;
  case base::ErrorCode::kUnsupported:
    return service::TileStatus::kUnsupported;
  default:
    return service::TileStatus::kFailed;
  }
}

TileService::TileService(construction::WorldData world)
    : world_(std::move(world)), evaluator_(world_),
      web_(tiling::TileScheme::webMercator(geometry::LocalProjection(
          world_.data().projectionCenter.x, world_.data().projectionCenter.y))),
      local_(tiling::TileScheme::localFor(world_.land().bounds())),
      geographic_(tiling::TileScheme::geographic(geometry::LocalProjection(
          world_.data().projectionCenter.x, world_.data().projectionCenter.y))) {
  renderers_[static_cast<std::size_t>(TileKind::kHeightmap)] =
      std::make_unique<HeightmapRenderer>();
  renderers_[static_cast<std::size_t>(TileKind::kMesh)] = std::make_unique<MeshRenderer>();
  renderers_[static_cast<std::size_t>(TileKind::kTerrain)] =
      std::make_unique<CesiumTerrainRenderer>(
          world_,
          geometry::LocalProjection(world_.data().projectionCenter.x,
                                    world_.data().projectionCenter.y),
          CesiumAvailability(worldBounds(world_.data()), geographic_.maxZoom()));
  renderers_[static_cast<std::size_t>(TileKind::kRelief)] = std::make_unique<ReliefRenderer>();
  renderers_[static_cast<std::size_t>(TileKind::kVector)] = std::make_unique<VectorTileRenderer>(
      world_, geometry::LocalProjection(world_.data().projectionCenter.x,
                                        world_.data().projectionCenter.y));
  renderers_[static_cast<std::size_t>(TileKind::kLayer)] = std::make_unique<LayerRenderer>(world_);
  renderers_[static_cast<std::size_t>(TileKind::kVegetation)] =
      std::make_unique<VegetationRenderer>(world_);
}

TileService::~TileService() = default;

base::Result<CheckedTile> TileService::checkTile(const TileRequest& request) const {
  if ((request.kind() == TileKind::kTerrain) != (request.scheme == tiling::SchemeKind::kGeographic))
    return base::makeError(base::ErrorCode::kInvalidInput,
                           "Cesium terrain tiles (.terrain) are served in the geographic pyramid "
                           "only, and only they are");
  if (request.kind() == TileKind::kLayer && request.scheme == tiling::SchemeKind::kGeographic)
    return base::makeError(base::ErrorCode::kInvalidInput,
                           "layer tiles are served in the Web Mercator and local pyramids");
  const tiling::TileScheme& s = scheme(request.scheme);
  const geometry::TileId& t = request.tile;
  if (!s.contains(t))
    return base::makeError(base::ErrorCode::kNotFound,
                           "tile " + std::to_string(t.z) + "/" + std::to_string(t.x) + "/" +
                               std::to_string(t.y) + " is outside the grid (zoom 0.." +
                               std::to_string(s.maxZoom()) + ")");
  return CheckedTile(request);
}

base::Result<RenderedTile> TileService::render(const TileRequest& request) const {
  STRAHLER_ASSIGN_OR_RETURN(const CheckedTile tile, checkTile(request));
  return render(tile);
}

base::Result<RenderedTile> TileService::render(const CheckedTile& tile) const {
  const TileRequest& request = tile.request();
  const TileSizeRange range = tileSizeRange(request.kind());
  const int size = request.options.size == 0 ? range.defaultSize : request.options.size;
  if (size < range.min || size > range.max)
    return base::makeError(base::ErrorCode::kOutOfRange,
                           "size " + std::to_string(size) + " is outside [" +
                               std::to_string(range.min) + ", " + std::to_string(range.max) +
                               "] for this format");
  const TileRenderer& renderer = *renderers_[static_cast<std::size_t>(request.kind())];
  return renderer.render(RenderContext{evaluator_, scheme(request.scheme)}, request, size);
}

} // namespace strahler::app
