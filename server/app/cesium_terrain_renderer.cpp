#include "cesium_terrain_renderer.h"

#include "render_clock.h"

#include "strahler/encoding/quantized_mesh.h"

#include <algorithm>
#include <utility>

namespace strahler::app {

CesiumTerrainRenderer::CesiumTerrainRenderer(const construction::World& world,
                                             const geometry::LocalProjection& projection,
                                             CesiumAvailability availability)
    : water_(world, projection), availability_(std::move(availability)) {}

base::Result<RenderedTile> CesiumTerrainRenderer::render(const RenderContext& context,
                                                         const TileRequest& request,
                                                         int size) const {
  RenderedTile out;
  const geometry::TileId& tile = request.tile;
  const unsigned extensions = request.options.extensions;
  const geometry::Aabb box = context.scheme.geographicBounds(tile);
  const encoding::GeographicRect rect{box.min.x, box.min.y, box.max.x, box.max.y};
  encoding::QuantizedMeshOptions options;
  options.maxError = encoding::cesiumLevelGeometricError(tile.z);
  options.normals = (extensions & kOctVertexNormals) != 0;
  if (extensions & kMetadata)
    options.metadata = availability_.metadataJson(tile);

  if (!availability_.available(tile)) {
    const auto start = RenderClock::now();
    if (extensions & kWaterMask)
      options.waterMask = {tiling::WaterMask::kWater};
    STRAHLER_ASSIGN_OR_RETURN(out.bytes, encoding::encodeEllipsoidTile(rect, options));
    out.encodeMs = millisecondsSince(start);
  } else {
    encoding::QuantizedMeshGrid grid;
    grid.rect = rect;
    grid.samples = size + 1;
    // meshGrid's rows start at the south border row, as the grid's do.
    grid.heights = evaluateGrid(context, context.scheme.meshGrid(tile, size), out);
    const auto start = RenderClock::now();
    for (double& h : grid.heights)
      h = std::max(h, 0.0); // the sea and lakes at their surface: Cesium draws the water there
    if (extensions & kWaterMask)
      options.waterMask = water_.of(box);
    STRAHLER_ASSIGN_OR_RETURN(out.bytes, encoding::encodeQuantizedMesh(grid, options));
    out.encodeMs = millisecondsSince(start);
  }
  gzipIfAsked(request, out);
  out.mimeType = "application/vnd.quantized-mesh";
  return out;
}

} // namespace strahler::app
