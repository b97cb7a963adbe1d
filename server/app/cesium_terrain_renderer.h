#pragma once

#include "cesium_availability.h"
#include "tile_renderer.h"

#include "strahler/construction/world.h"
#include "strahler/geometry/projection.h"
#include "strahler/tiling/water_mask.h"

namespace strahler::app {

/// Renders TileKind::kTerrain: Cesium quantized-mesh-1.0 tiles of the geographic pyramid. An
/// available tile is meshed from the world's heights on a (size + 1)² grid (plus a border for
/// the normals) to the level's geometric error, the sea and lakes at their surface (0 m, the
/// ellipsoid); any other tile is the ellipsoid. The extensions asked for are added: normals
/// from the heights, the water mask of the world's sea, lakes and rivers, and the
/// availability of the levels below as metadata. Gzipped when asked.
class CesiumTerrainRenderer final : public TileRenderer {
public:
  /// A renderer over `world` (which must outlive it), seen through `projection`.
  CesiumTerrainRenderer(const construction::World& world,
                        const geometry::LocalProjection& projection,
                        CesiumAvailability availability);

  /// See TileRenderer::render.
  base::Result<RenderedTile> render(const RenderContext& context, const TileRequest& request,
                                    int size) const override;

private:
  tiling::WaterMask water_;
  CesiumAvailability availability_;
};

} // namespace strahler::app
