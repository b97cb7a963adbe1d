#include "vector_tile_renderer.h"

#include "render_clock.h"

#include "strahler/vector_tile/vector_tile.h"

namespace strahler::app {

VectorTileRenderer::VectorTileRenderer(const construction::World& world,
                                       const geometry::LocalProjection& projection)
    : world_(world), projection_(projection) {}

const WorldVectors& VectorTileRenderer::vectors() const {
  std::call_once(once_, [this] { vectors_ = projectWorldVectors(world_.data(), projection_); });
  return vectors_;
}

base::Result<RenderedTile> VectorTileRenderer::render(const RenderContext& context,
                                                      const TileRequest& request, int) const {
  if (context.scheme.kind() != tiling::SchemeKind::kWebMercator)
    return base::makeError(base::ErrorCode::kInvalidInput,
                           "vector tiles (mvt) are served in the Web Mercator pyramid only");
  RenderedTile out;
  const tiling::SampleGrid grid = context.scheme.borderedRasterGrid(request.tile, kContourGrid);
  const std::vector<double> heights = evaluateGrid(context, grid, out);
  const auto start = RenderClock::now();
  const WorldVectors& world = vectors();
  vector_tile::Tile tile;
  tile.layers.push_back(waterLayer(world, request.tile));
  tile.layers.push_back(contoursLayer(heights, request.tile.z));
  tile.layers.push_back(riversLayer(world, request.tile));
  tile.layers.push_back(featuresLayer(world, request.tile));
  out.bytes = vector_tile::encodeTile(tile);
  out.mimeType = "application/vnd.mapbox-vector-tile";
  out.encodeMs = millisecondsSince(start);
  gzipIfAsked(request, out);
  return out;
}

} // namespace strahler::app
