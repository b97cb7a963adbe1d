#pragma once

#include "tile_renderer.h"

namespace strahler::app {

/// Largest position error (m) a mesh tile's Draco quantisation may introduce: 1 cm, or a
/// thousandth of the vertex spacing on coarse tiles (kilometre-wide tiles cannot keep 1 cm in
/// float32 coordinates).
double meshPositionError(double vertexSpacing) noexcept;

/// Renders TileKind::kMesh: a grid mesh of size × size quads with skirts, Draco-compressed
/// (drc) or as glTF with KHR_draco_mesh_compression (glb).
class MeshRenderer final : public TileRenderer {
public:
  /// See TileRenderer::render.
  base::Result<RenderedTile> render(const RenderContext& context, const TileRequest& request,
                                    int size) const override;
};

} // namespace strahler::app
