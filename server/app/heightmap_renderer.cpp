#include "heightmap_renderer.h"

#include "render_clock.h"

#include "strahler/encoding/heightmap_encoder.h"

#include <vector>

namespace strahler::app {
namespace {

encoding::HeightmapFormat heightmapFormat(TileFormat f) {
  switch (f) {
  case TileFormat::kTerrarium:
    return encoding::HeightmapFormat::kTerrarium;
  case TileFormat::kPng16:
    return encoding::HeightmapFormat::kPng16;
  case TileFormat::kTiff:
    return encoding::HeightmapFormat::kTiff;
  case TileFormat::kExr:
    return encoding::HeightmapFormat::kExr;
  default:
    return encoding::HeightmapFormat::kTerrainRgb;
  }
}

} // namespace

base::Result<RenderedTile> HeightmapRenderer::render(const RenderContext& context,
                                                     const TileRequest& request, int size) const {
  RenderedTile out;
  const std::vector<double> heights =
      evaluateGrid(context, context.scheme.rasterGrid(request.tile, size), out);
  const auto start = RenderClock::now();
  encoding::HeightGrid g{size, size, std::vector<float>(heights.begin(), heights.end())};
  const encoding::HeightmapFormat f = heightmapFormat(request.format);
  STRAHLER_ASSIGN_OR_RETURN(out.bytes, encoding::encodeHeightmap(g, f));
  out.mimeType = encoding::mimeType(f);
  out.encodeMs = millisecondsSince(start);
  return out;
}

} // namespace strahler::app
