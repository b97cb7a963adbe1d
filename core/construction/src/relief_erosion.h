#pragma once

#include "strahler/base/stage_timer.h"
#include "strahler/construction/world_data.h"

namespace strahler::construction::detail {

/// Erosion at generation (issue 36): evaluates the construction tree of `data` (whose relief
/// must be empty) on the global lattice of data.params.erosionCell over its land, runs the
/// landscape evolution (core/landscape) with the sea, lakes and the graph's river lines as
/// fixed base levels and erodibility and diffusivity varying by place, and stores the residual
/// eroded − tree in data.relief. Nothing with erosionSteps = 0. Deterministic for any thread
/// count. `progress` gets ("erosion", fraction).
void erodeRelief(WorldData& data, const base::ProgressCallback& progress = {});

} // namespace strahler::construction::detail
