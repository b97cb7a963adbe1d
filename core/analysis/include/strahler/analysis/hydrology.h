#pragma once

#include "strahler/analysis/network_analysis.h"
#include "strahler/base/result.h"
#include "strahler/base/stage_timer.h"
#include "strahler/blocks/block_set.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/input/world_spec.h"
#include "strahler/network/river_network.h"

#include <memory>

namespace strahler::analysis {

/// Everything the first half of the pipeline produces: the indexed land, the river graph,
/// its Voronoi blocks and their analysis.
struct Hydrology {
  std::unique_ptr<geometry::PolygonIndex> land; ///< Stable address: ReliefLaw refers to it.
  network::RiverNetwork network;
  blocks::BlockSet blocks;
  NetworkAnalysis analysis;
};

/// Runs mouths + growth ("network"), segmentation ("blocks") and analysis ("analysis") on
/// `spec`, reporting progress and recording each stage's time in `timer` when given.
base::Result<Hydrology> buildHydrology(const input::WorldSpec& spec,
                                       const base::ProgressCallback& progress = {},
                                       base::StageTimer* timer = nullptr);

} // namespace strahler::analysis
