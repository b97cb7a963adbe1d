#pragma once

#include "strahler/construction/world.h"
#include "strahler/construction/world_data.h"
#include "strahler/input/world_spec.h"
#include "strahler/primitives/terrain_primitives.h"

#include <vector>

namespace strahler::construction::detail {

/// How far from a drawn mountain's point its summit is looked for, m: the height a mountain
/// reaches is the world's highest point within this distance of where it was drawn.
inline constexpr double kSummitReach = 1000.0;

/// Shapes the terrain primitives of `data` by the drawn features (docs/architecture.md, "Vector
/// map: mountains and ridgelines") and then fits the river primitives' valleys to them
/// (primitives::fitValleyRadii): every drawn mountain with an `elevation` reaches it, its gain
/// scaling the relief above the rivers around it (primitives::mountainGain, scaleRelief of
/// data.terrain[i] above bases[i]), then the ridgelines lift their crests
/// (primitives::liftCrests). The gains are found by secant steps on the height that a World of
/// the primitives near the summits, shaped so, reaches (kSummitReach): at most four such small
/// worlds, keeping each mountain's best. `data` is complete but for its valleys' fit.
void fitDrawnMountains(const input::WorldSpec& spec, WorldData& data,
                       const std::vector<primitives::TerrainBase>& bases);

/// The highest height of `world` within `reach` of p: sampled every `spacing` metres, then
/// every spacing / 4 around the highest sample.
double highestWithin(const World& world, geometry::Vec2 p, double reach, double spacing);

} // namespace strahler::construction::detail
