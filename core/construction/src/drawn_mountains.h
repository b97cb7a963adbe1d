#pragma once

#include "strahler/construction/world.h"
#include "strahler/construction/world_data.h"
#include "strahler/input/world_spec.h"

#include <vector>

namespace strahler::construction::detail {

/// How far from a drawn mountain's point its summit is looked for, m: the height a mountain
/// reaches is the world's highest point within this distance of where it was drawn.
inline constexpr double kSummitReach = 1000.0;

/// Fits the river primitives' valleys to the terrain (primitives::fitValleyRadii) after making
/// every drawn mountain with an `elevation` reach it (docs/architecture.md, "Vector map:
/// mountains and ridgelines"): each mountain's gain scales the relief above the rivers around
/// it (primitives::mountainGain, primitives::scaleRelief of data.terrain[i] above bases[i]).
/// The gains are found by secant steps on the height a World made of the primitives near the
/// summits reaches (kSummitReach), at most four such worlds, keeping each mountain's best.
/// `data` is complete but for the fit of its rivers' valleys.
void fitDrawnMountains(const input::WorldSpec& spec, WorldData& data,
                       const std::vector<double>& bases);

/// The highest height of `world` within `reach` of p: sampled every `spacing` metres, then
/// every spacing / 4 around the highest sample.
double highestWithin(const World& world, geometry::Vec2 p, double reach, double spacing);

} // namespace strahler::construction::detail
