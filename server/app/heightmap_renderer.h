#pragma once

#include "tile_renderer.h"

namespace strahler::app {

/// Renders TileKind::kHeightmap: a size × size raster of heights, encoded as the request's
/// format (Terrain-RGB, Terrarium, 16-bit PNG, TIFF, EXR).
class HeightmapRenderer final : public TileRenderer {
public:
  /// See TileRenderer::render.
  base::Result<RenderedTile> render(const RenderContext& context, const TileRequest& request,
                                    int size) const override;
};

} // namespace strahler::app
