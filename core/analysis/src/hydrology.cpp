#include "strahler/analysis/hydrology.h"

#include "strahler/analysis/river_profiles.h"
#include "strahler/network/network_growth.h"

namespace strahler::analysis {

base::Result<Hydrology> buildHydrology(const input::WorldSpec& spec,
                                       const base::ProgressCallback& progress,
                                       base::StageTimer* timer) {
  auto stage = [&](const char* name) {
    if (timer)
      timer->start(name);
    if (progress)
      progress(name, 0.0);
  };
  Hydrology h;
  stage("network");
  h.land = std::make_unique<geometry::PolygonIndex>(spec.land);
  STRAHLER_ASSIGN_OR_RETURN(h.network, network::generateNetwork(spec, *h.land, progress));
  stage("blocks");
  STRAHLER_ASSIGN_OR_RETURN(h.blocks, blocks::buildBlocks(h.network, *h.land));
  if (progress)
    progress("blocks", 1.0);
  stage("analysis");
  shapeRiverProfiles(spec, *h.land, h.blocks, h.network);
  h.analysis = analyzeNetwork(spec, *h.land, h.network, h.blocks);
  if (progress)
    progress("analysis", 1.0);
  if (timer)
    timer->finish();
  return h;
}

} // namespace strahler::analysis
