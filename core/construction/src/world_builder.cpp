#include "strahler/construction/world_builder.h"

#include "drawn_mountains.h"
#include "relief_erosion.h"

#include "strahler/analysis/hydrology.h"
#include "strahler/primitives/quantization.h"
#include "strahler/primitives/river_primitives.h"
#include "strahler/primitives/terrain_primitives.h"

namespace strahler::construction {
namespace {

using primitives::quantize;
using primitives::Quantum;

/// Snaps node positions and elevations to the file's precision, keeping every child higher
/// than its parent.
void quantizeNetwork(network::RiverNetwork& network) {
  for (network::RiverNode& n : network.nodes) {
    n.position = quantize(n.position);
    n.elevation = quantize(n.elevation, Quantum::kElevation);
    if (n.parent.valid()) {
      const double below = network.nodes[n.parent.index()].elevation;
      if (n.elevation <= below)
        n.elevation = below + Quantum::kElevation;
    }
  }
}

geometry::MultiPolygon quantizeLand(geometry::MultiPolygon land) {
  for (geometry::Polygon& p : land) {
    for (geometry::Vec2& v : p.outer)
      v = quantize(v);
    for (geometry::Ring& h : p.holes)
      for (geometry::Vec2& v : h)
        v = quantize(v);
  }
  return land;
}

} // namespace

base::Result<WorldData> generateWorldData(const input::WorldSpec& spec, std::string cacheKey,
                                          const base::ProgressCallback& progress,
                                          base::StageTimer* timer) {
  STRAHLER_ASSIGN_OR_RETURN(analysis::Hydrology hydrology,
                            analysis::buildHydrology(spec, progress, timer));
  if (timer)
    timer->start("primitives");
  if (progress)
    progress("primitives", 0.0);
  quantizeNetwork(hydrology.network);

  WorldData data;
  data.name = spec.name;
  data.cacheKey = std::move(cacheKey);
  data.generatorVersion = kGeneratorVersion;
  data.params = spec.params;
  data.features = spec.features;
  data.projectionCenter = spec.projection.center();
  data.land = quantizeLand(spec.land);
  data.rivers = primitives::generateRiverPrimitives(
      spec.params, hydrology.network, hydrology.analysis, *hydrology.land, spec.features);
  // With drawn features: the river heights the primitives rise from, for the mountains' fit.
  const bool drawn = !spec.features.empty();
  std::vector<std::vector<primitives::TerrainBase>> basesByBlock;
  const auto terrainByBlock = primitives::generateTerrainPrimitives(
      spec, hydrology, data.rivers, drawn ? &basesByBlock : nullptr);
  if (progress)
    progress("primitives", 0.9);

  // Group by block: block i holds its terrain and the river section below node i.
  std::vector<primitives::TerrainBase> bases;
  std::uint32_t river = 0;
  for (std::uint32_t i = 0; i < hydrology.network.nodes.size(); ++i) {
    BlockPrimitives b;
    b.terrainBegin = static_cast<std::uint32_t>(data.terrain.size());
    data.terrain.insert(data.terrain.end(), terrainByBlock[i].begin(), terrainByBlock[i].end());
    if (drawn)
      bases.insert(bases.end(), basesByBlock[i].begin(), basesByBlock[i].end());
    b.terrainEnd = static_cast<std::uint32_t>(data.terrain.size());
    b.riverBegin = river;
    if (hydrology.network.nodes[i].parent.valid())
      ++river;
    b.riverEnd = river;
    data.blocks.push_back(b);
  }
  for (std::size_t i = 0; i < hydrology.network.nodes.size(); ++i) {
    data.flow.push_back(quantize(hydrology.analysis.flow[i], Quantum::kFlow));
    data.riverTypes.push_back(primitives::toRiverType(hydrology.analysis.rosgen[i]));
  }
  data.network = std::move(hydrology.network);
  if (drawn)
    detail::fitDrawnMountains(spec, data, bases);
  else
    primitives::fitValleyRadii(data.rivers, data.terrain);
  if (progress)
    progress("primitives", 1.0);
  if (timer)
    timer->start("erosion");
  detail::erodeRelief(data, progress);
  if (timer) {
    timer->finish();
    data.stageSeconds = timer->stages();
  }
  return data;
}

} // namespace strahler::construction
