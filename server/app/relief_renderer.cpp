#include "relief_renderer.h"

#include "render_clock.h"

#include "strahler/encoding/rgb_png.h"
#include "strahler/render/shaded_relief.h"

#include <vector>

namespace strahler::app {

base::Result<RenderedTile> ReliefRenderer::render(const RenderContext& context,
                                                  const TileRequest& request, int size) const {
  RenderedTile out;
  const tiling::SampleGrid grid = context.scheme.borderedRasterGrid(request.tile, size);
  const std::vector<double> heights = evaluateGrid(context, grid, out);
  const auto start = RenderClock::now();
  const image::RgbImage picture = render::shadeRelief(heights, size, size, grid.rowSpacing);
  STRAHLER_ASSIGN_OR_RETURN(out.bytes, encoding::encodeRgbPng(picture.pixels, size, size));
  out.mimeType = "image/png";
  out.encodeMs = millisecondsSince(start);
  return out;
}

} // namespace strahler::app
