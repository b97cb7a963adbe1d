#include "vegetation_renderer.h"

#include "lattice_density.h"
#include "render_clock.h"

#include "strahler/vegetation/vegetation_json.h"

#include <string>

namespace strahler::app {
namespace {

/// "zooms 16 to 18": the zooms with vegetation, for the refusal of the others.
std::string vegetationZooms() {
  int first = -1, last = -1;
  for (int z = 0; z <= vegetation::kMaxVegetationZoom; ++z)
    if (vegetation::visibleSpecies(z) != 0) {
      first = first < 0 ? z : first;
      last = z;
    }
  return "zooms " + std::to_string(first) + " to " + std::to_string(last);
}

} // namespace

VegetationRenderer::VegetationRenderer(const construction::World& world)
    : world_(world), water_(world, geometry::LocalProjection(world.data().projectionCenter.x,
                                                             world.data().projectionCenter.y)) {}

base::Result<RenderedTile> VegetationRenderer::render(const RenderContext& context,
                                                      const TileRequest& request, int) const {
  if (context.scheme.kind() != tiling::SchemeKind::kWebMercator)
    return base::makeError(base::ErrorCode::kInvalidInput,
                           "vegetation tiles are served in the Web Mercator pyramid only");
  const geometry::TileId& tile = request.tile;
  if (vegetation::visibleSpecies(tile.z) == 0)
    return base::makeError(base::ErrorCode::kNotFound,
                           "no vegetation at zoom " + std::to_string(tile.z) +
                               ": individuals are served at " + vegetationZooms());
  RenderedTile out;
  const LatticeDensity density(context, world_, water_, tile, out);
  const auto start = RenderClock::now();
  const geometry::LocalProjection projection(world_.data().projectionCenter.x,
                                             world_.data().projectionCenter.y);
  STRAHLER_ASSIGN_OR_RETURN(
      const std::vector<vegetation::Instance> instances,
      vegetation::placeWebTile(world_.data().params.seed, projection, tile, density));
  std::vector<double> heights; // the ground under each plant, for clients that stand them on it
  heights.reserve(instances.size());
  for (const vegetation::Instance& i : instances)
    heights.push_back(density.heightAt(i.position));
  out.bytes = vegetation::writeVegetationJson(tile, projection, instances, heights);
  out.mimeType = "application/json";
  out.encodeMs = millisecondsSince(start);
  gzipIfAsked(request, out);
  return out;
}

} // namespace strahler::app
