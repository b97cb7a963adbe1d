#pragma once

#include "tile_renderer.h"

namespace strahler::app {

/// Renders TileKind::kRelief: a size × size 8-bit RGB PNG of the tile's heights in colour
/// (render::hypsometricTint, the same ramp in every tile and world) times a hillshade
/// (render::hillshade) whose slopes use the neighbouring tiles' edge pixels, so that tiles
/// join without a seam. Its pixels sample the heightmap tiles' points (rasterGrid).
class ReliefRenderer final : public TileRenderer {
public:
  /// See TileRenderer::render.
  base::Result<RenderedTile> render(const RenderContext& context, const TileRequest& request,
                                    int size) const override;
};

} // namespace strahler::app
