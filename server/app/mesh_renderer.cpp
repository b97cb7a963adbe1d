#include "mesh_renderer.h"

#include "render_clock.h"

#include "strahler/encoding/mesh.h"
#include "strahler/encoding/mesh_encoder.h"

#include <algorithm>
#include <tuple>
#include <vector>

namespace strahler::app {
namespace {

/// Skirt depth: half the vertex spacing, at least 1 m — more than the height difference
/// between neighbouring levels of detail at slopes up to ~1:2.
double skirtDepth(double vertexSpacing) {
  return std::max(1.0, 0.5 * vertexSpacing);
}

} // namespace

double meshPositionError(double vertexSpacing) noexcept {
  return std::max(0.01, vertexSpacing * 1e-3);
}

base::Result<RenderedTile> MeshRenderer::render(const RenderContext& context,
                                                const TileRequest& request, int size) const {
  RenderedTile out;
  const std::vector<double> heights =
      evaluateGrid(context, context.scheme.meshGrid(request.tile, size), out);
  const auto start = RenderClock::now();
  encoding::MeshGridInput input;
  input.quads = size;
  std::tie(input.origin, input.spacing) = context.scheme.meshFrame(request.tile, size);
  input.heights.assign(heights.begin(), heights.end());
  input.skirtDepth = skirtDepth(input.spacing);
  STRAHLER_ASSIGN_OR_RETURN(const encoding::Mesh m, encoding::buildGridMesh(input));
  const encoding::DracoOptions draco{meshPositionError(input.spacing)};
  const bool glb = request.format == TileFormat::kGlb;
  STRAHLER_ASSIGN_OR_RETURN(out.bytes,
                            glb ? encoding::encodeGlb(m, draco) : encoding::encodeDraco(m, draco));
  out.mimeType = glb ? "model/gltf-binary" : "application/octet-stream";
  out.encodeMs = millisecondsSince(start);
  return out;
}

} // namespace strahler::app
