#pragma once

#include "tile_renderer.h"

#include "strahler/construction/world.h"
#include "strahler/tiling/water_mask.h"

namespace strahler::app {

/// Renders TileKind::kLayer: a size × size grey PNG of one derived layer (LayerName, with the
/// encoding it documents) computed by core/layers from the tile's heights with a border of the
/// neighbouring tiles' samples (one pixel; SkyView::kReach for illumination and vegetation) and
/// the world's rivers, so that tiles join without a seam. Its pixels sample the heightmap
/// tiles' points (rasterGrid). kLocal and kWebMercator pyramids.
class LayerRenderer final : public TileRenderer {
public:
  /// A renderer over `world` (which must outlive it), for its water and rivers.
  explicit LayerRenderer(const construction::World& world);

  /// See TileRenderer::render.
  base::Result<RenderedTile> render(const RenderContext& context, const TileRequest& request,
                                    int size) const override;

private:
  const construction::World& world_;
  tiling::WaterMask water_;
};

} // namespace strahler::app
