#pragma once

#include "strahler/base/result.h"
#include "strahler/base/stage_timer.h"
#include "strahler/construction/world_data.h"
#include "strahler/input/world_spec.h"

#include <string>

namespace strahler::construction {

/// Version of the generator; part of every cache key (and so of every tile's ETag), so
/// changing what the generator makes, or how a world evaluates, invalidates cached worlds.
/// 2: the terrain blend mixes noise amplitude and roughness (docs/architecture.md).
/// 5: rule 1 (fill) gives at most two children (binary confluences); concave river
/// profiles, valleys scaled to the catchment, gully relief octaves.
/// 6: river floors at the sample spacing, rivers joined by the deeper cut, sloping terrain
/// primitives, valleys that widen with their depth (fitted radii), λ 0.35, concavity 0.3.
/// 7: rivers fade in from one sample spacing (primitives::riverFade); growth goes back to the
/// land far from every river (the coverage gaps).
/// 8: river curves are sine-generated meanders joined smoothly at the nodes (issue 36), and
/// coastlines are canonical (either winding, any first vertex). Erosion at generation is opt-in
/// through params (erosionSteps > 0, part of the canonical params and so of the cache key).
inline constexpr const char* kGeneratorVersion = "strahler-generator-9";

/// Runs the whole generation of Sections 4–7 on `spec`: network, blocks and analysis
/// (analysis::buildHydrology), then river and terrain primitives ("primitives"), quantised to
/// the file's precision, then, where params.erosionSteps > 0, erosion at generation (the
/// residual in WorldData::relief). `cacheKey` is recorded in the result. Stages are timed into
/// `timer`.
base::Result<WorldData> generateWorldData(const input::WorldSpec& spec, std::string cacheKey,
                                          const base::ProgressCallback& progress = {},
                                          base::StageTimer* timer = nullptr);

} // namespace strahler::construction
