#include "tile_service.h"

#include "strahler/encoding/heightmap_encoder.h"
#include "strahler/encoding/mesh.h"
#include "strahler/encoding/mesh_encoder.h"

#include <algorithm>
#include <chrono>

namespace strahler::app {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

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

/// Skirt depth: half the vertex spacing, at least 1 m — more than the height difference
/// between neighbouring levels of detail at slopes up to ~1:2.
double skirtDepth(double vertexSpacing) {
  return std::max(1.0, 0.5 * vertexSpacing);
}

} // namespace

double meshPositionError(double vertexSpacing) noexcept {
  return std::max(0.01, vertexSpacing * 1e-3);
}

TileService::TileService(construction::WorldData world)
    : world_(std::move(world)), evaluator_(world_),
      web_(tiling::TileScheme::webMercator(geometry::LocalProjection(
          world_.data().projectionCenter.x, world_.data().projectionCenter.y))),
      local_(tiling::TileScheme::localFor(world_.land().bounds())) {}

base::Result<RenderedTile> TileService::render(const TileRequest& request) const {
  const tiling::TileScheme& s = scheme(request.scheme);
  const tiling::TileId& t = request.tile;
  if (!s.contains(t))
    return base::makeError(base::ErrorCode::kNotFound,
                           "tile " + std::to_string(t.z) + "/" + std::to_string(t.x) + "/" +
                               std::to_string(t.y) + " is outside the grid (zoom 0.." +
                               std::to_string(s.maxZoom()) + ")");
  const bool mesh = isMeshFormat(request.format);
  const int lo = mesh ? TileSizes::kMeshMin : TileSizes::kRasterMin;
  const int hi = mesh ? TileSizes::kMeshMax : TileSizes::kRasterMax;
  const int size = request.size == 0 ? (mesh ? TileSizes::kMeshDefault : TileSizes::kRasterDefault)
                                     : request.size;
  if (size < lo || size > hi)
    return base::makeError(base::ErrorCode::kOutOfRange,
                           "size " + std::to_string(size) + " is outside [" + std::to_string(lo) +
                               ", " + std::to_string(hi) + "] for this format");
  RenderedTile out;
  auto start = Clock::now();
  const tiling::SampleGrid grid = mesh ? s.meshGrid(t, size) : s.rasterGrid(t, size);
  const std::vector<double> heights = evaluator_.evaluate(grid, &out.stats);
  out.evaluateMs = millisecondsSince(start);
  start = Clock::now();
  if (mesh) {
    encoding::MeshGridInput input;
    input.quads = size;
    std::tie(input.origin, input.spacing) = s.meshFrame(t, size);
    input.heights.assign(heights.begin(), heights.end());
    input.skirtDepth = skirtDepth(input.spacing);
    STRAHLER_ASSIGN_OR_RETURN(const encoding::Mesh m, encoding::buildGridMesh(input));
    const encoding::DracoOptions draco{meshPositionError(input.spacing)};
    STRAHLER_ASSIGN_OR_RETURN(out.bytes, request.format == TileFormat::kGlb
                                             ? encoding::encodeGlb(m, draco)
                                             : encoding::encodeDraco(m, draco));
    out.mimeType =
        request.format == TileFormat::kGlb ? "model/gltf-binary" : "application/octet-stream";
  } else {
    encoding::HeightGrid g{size, size, std::vector<float>(heights.begin(), heights.end())};
    const encoding::HeightmapFormat f = heightmapFormat(request.format);
    STRAHLER_ASSIGN_OR_RETURN(out.bytes, encoding::encodeHeightmap(g, f));
    out.mimeType = encoding::mimeType(f);
  }
  out.encodeMs = millisecondsSince(start);
  return out;
}

} // namespace strahler::app
