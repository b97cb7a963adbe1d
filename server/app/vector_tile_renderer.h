#pragma once

#include "tile_renderer.h"
#include "vector_layers.h"

#include "strahler/construction/world.h"
#include "strahler/geometry/projection.h"

#include <mutex>

namespace strahler::app {

/// Renders TileKind::kVector: a Mapbox Vector Tile 2.1 (extent 4096, buffer kVectorBuffer) of
/// the Web Mercator pyramid with the layers water, contours (traced on the tile's heights),
/// rivers and features (vector_layers.h). It reads more than the context's heights: the
/// world's rivers, land and vector map, which it is given at construction (as the Cesium
/// renderer is) and projects once, on its first tile. Gzipped when asked.
class VectorTileRenderer final : public TileRenderer {
public:
  /// A renderer over `world` (which must outlive it), seen through `projection`.
  VectorTileRenderer(const construction::World& world, const geometry::LocalProjection& projection);

  /// See TileRenderer::render; kInvalidInput outside the Web Mercator pyramid.
  base::Result<RenderedTile> render(const RenderContext& context, const TileRequest& request,
                                    int size) const override;

private:
  /// The world's projected geometry, made on first use (a world that never serves a vector
  /// tile never pays for it).
  const WorldVectors& vectors() const;

  const construction::World& world_;
  geometry::LocalProjection projection_;
  mutable std::once_flag once_;
  mutable WorldVectors vectors_;
};

} // namespace strahler::app
