#pragma once

#include "strahler/input/world_spec.h"
#include "strahler/primitives/river_primitive.h"
#include "strahler/primitives/terrain_primitive.h"
#include "strahler/primitives/terrain_primitives.h"

#include <optional>
#include <span>
#include <vector>

namespace strahler::primitives {

/// Drop of a drawn ridgeline's crest per metre away from the line (its flanks), m/m.
inline constexpr double kCrestFlank = 0.3;
/// How far the crest may rise above the highest primitive near it, m.
inline constexpr double kCrestRise = 60.0;
/// How far from a drawn ridgeline the crest stands above every primitive, m.
inline constexpr double kCrestReach = 1500.0;
/// Distance from a river over which a crest's lift fades in, m: the terrain beside a river
/// stays at the river's height, so rivers keep below their banks.
inline constexpr double kCrestRiverClearance = 150.0;

/// Lifts the terrain primitives along spec.features' drawn ridgelines into continuous crests
/// (docs/architecture.md, "Vector map: mountains and ridgelines"). Along each ridge a crest
/// height Z(s) is set every 100 m of its length: the highest e + kCrestFlank d of the primitives
/// within kCrestReach (e its elevation, d its distance to the line) and the ridge's `elevation`
/// when given, then a running max and a running mean over ±1 km, which keep Z above each of
/// those and make it continuous. A primitive at distance d < W (the ridge's half-width,
/// network::ridgeHalfWidth) is raised towards the tent Z − kCrestFlank d, its plane turned down
/// the tent, by a share that fades in with the distance to its river (bases: what
/// generateTerrainPrimitives reports, one per primitive) and out from W/2 to W; its noise
/// amplitude is lowered within 1 km of the line. Within kCrestReach every primitive then lies
/// on or below the tent, so a profile across the line peaks on it. A no-op without ridges.
void liftCrests(const input::WorldSpec& spec, std::vector<TerrainPrimitive>& terrain,
                std::span<const TerrainBase> bases);

/// How far a river's valley stops short of a drawn ridgeline, m.
inline constexpr double kValleyCrestMargin = 60.0;
/// Narrows the valleys (radii) of `rivers` that would reach over a drawn ridgeline of spec to
/// stop kValleyCrestMargin short of it, no narrower than valleyMinReach: the crest is not
/// carved by the valleys beside it. Run after fitValleyRadii; a no-op without ridges.
void keepValleysOffCrests(const input::WorldSpec& spec, std::vector<RiverPrimitive>& rivers);

/// Radii (m) of spec.features' mountains (network::mountainRadius), in order.
std::vector<double> mountainRadii(const input::WorldSpec& spec);
/// Gain of the drawn mountains at p: 1 plus the largest and the most negative of
/// (gains[m] − 1) · smoothstep(1 − d_m / radii[m]), d_m the distance to mountain m: each scales
/// the relief around it, most at its summit, and overlapping reaches do not add up.
double mountainGain(const input::Features& features, std::span<const double> radii,
                    std::span<const double> gains, geometry::Vec2 p) noexcept;
/// How far a drawn summit's cone falls per metre from it: no primitive within a mountain's
/// radius is raised above elevation − kSummitFall · d, so the summit stays the highest point.
inline constexpr double kSummitFall = 0.15;
/// The highest elevation a primitive at p may be raised to: the largest of elevation −
/// kSummitFall · d over the drawn mountains with an `elevation` whose radius covers p; none
/// when no such mountain does.
std::optional<double> mountainCap(const input::Features& features, std::span<const double> radii,
                                  geometry::Vec2 p) noexcept;
/// t with its relief above `base` (the river height it rises from) scaled by `gain` ≥ 0:
/// elevation base + gain (elevation − base), raised no higher than `cap` (and never lowered by
/// it), plane and noise amplitude times gain; quantised.
TerrainPrimitive scaleRelief(const TerrainPrimitive& t, double base, double gain,
                             std::optional<double> cap = std::nullopt) noexcept;

} // namespace strahler::primitives
