#pragma once

#include "strahler/analysis/network_analysis.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/input/features.h"
#include "strahler/input/params.h"
#include "strahler/network/river_network.h"
#include "strahler/primitives/river_primitive.h"
#include "strahler/primitives/terrain_primitive.h"

#include <algorithm>
#include <vector>

namespace strahler::primitives {

/// The primitive river type of an analysed Rosgen type.
RiverType toRiverType(analysis::RosgenType type) noexcept;

/// Hydraulic geometry (Leopold & Maddock 1953 exponents): channel width 4 · φ^0.5 m and depth
/// 0.4 · φ^0.4 m for a mean flow φ in m³/s (φ = 10: 12.6 m wide, 1.0 m deep).
double channelWidth(double flow) noexcept;
/// Channel depth below the water surface for flow φ, m (see channelWidth).
double channelDepth(double flow) noexcept;
/// Half-width r of the valley a river of this type and channel width replaces, m: it grows
/// with the channel, so with the drainage area (a first-order stream's hollow is ~170 m wide
/// each side, a 25 m lowland river's valley ~1 km), wider for gentler types.
double valleyRadius(RiverType type, double width) noexcept;

/// Whether rivers of this type have the flatter bed of riverProfile(): braided rivers, deltas.
inline bool hasFlatBed(RiverType type) noexcept {
  return type == RiverType::kBraided || type == RiverType::kDelta;
}
/// The slope of the banks of riverProfile() for this type (steep V for B, gentle for E,
/// nearly flat for D).
inline double bankSlope(RiverType type) noexcept {
  constexpr double kBankSlope[] = {0.25, 0.06, 0.04, 0.02}; // by RiverType
  return kBankSlope[static_cast<int>(type)];
}

/// Metres of valley side per metre the terrain stands above a river's water (valleyReach): a
/// valley deep below its terrain widens so that its sides stay below about 35°.
inline constexpr double kValleyRunPerRise = 2.2;

/// How far a river's valley reaches where the terrain stands `rise` metres above its water:
/// kValleyRunPerRise · rise, at least `minReach` (valleyMinReach), at most the river's radius
/// (its support; the radius wins if smaller). Shallow valleys stay narrow, deep ones get long
/// sides instead of walls.
inline double valleyReach(double minReach, double radius, double rise) noexcept {
  return std::min(std::max(kValleyRunPerRise * rise, minReach), radius);
}

/// The least reach of a river's valley: half the radius of its type for its wider channel end
/// (valleyRadius), whatever radius fitValleyRadii gave it.
double valleyMinReach(RiverType type, double widthUp, double widthDown) noexcept;

/// Narrows each river's radius (its support, at first valleyRadius) to the reach its valley
/// can need: kValleyRunPerRise times the most that a terrain primitive within the radius (plus
/// half a terrain radius) stands above the river's water at the nearest curve point, with a
/// 15 % margin, between valleyMinReach and the radius; quantized. A wide support costs every
/// sample near it a longer curve search, so lowland rivers between low hills keep a small one.
void fitValleyRadii(std::vector<RiverPrimitive>& rivers,
                    const std::vector<TerrainPrimitive>& terrain);

/// Sample spacings a river's radius spans where it starts to fade out (riverFade). One: a
/// valley two samples wide is still drawn (at two, 14 % of Mallorca's land sampled every
/// 120 m drained into pits where the valleys had faded; at one, all of it drains).
inline constexpr double kRiverFadeSpacings = 1.0;

/// The LOD fade of a river of valley radius `radius` sampled every `spacing` metres (0:
/// exact), which scales its weight: 0 while the radius spans at most kRiverFadeSpacings
/// samples (a valley too narrow for the samples, as an octave of noise fades below two
/// samples per wavelength), 1 from twice that. Evaluation skips rivers whose fade is 0.
inline double riverFade(double radius, double spacing) noexcept {
  if (spacing <= 0.0)
    return 1.0;
  return std::clamp(radius / (kRiverFadeSpacings * spacing) - 1.0, 0.0, 1.0);
}

/// 1 / floor, or a huge number for floor 0 (every channel resolved), as evaluation computes it.
inline double riverFloorInverse(double floor) noexcept {
  return floor > 0.0 ? 1.0 / floor : 1e300;
}

/// Sample spacings in the half-width of the flat floor a river's section gets at a given
/// sample spacing (riverFloor): 1.5 spacings across, so that a row of samples along any
/// channel direction falls on the floor and descends with it (a channel narrower than the
/// samples would otherwise be sampled at varying depths and read as a chain of pits).
inline constexpr double kFloorPerSpacing = 0.75;

/// The half-width, m, of the flat floor of a river whose valley reaches at least `minReach`
/// (valleyMinReach) sampled every `spacing` metres (0: exact): kFloorPerSpacing · spacing, at
/// most half the least reach. The LOD rule for rivers: detail narrower than the samples fades
/// into the floor.
inline double riverFloor(double minReach, double spacing) noexcept {
  return std::min(kFloorPerSpacing * spacing, 0.5 * minReach);
}

/// The profile δ(d) across a river, relative to its water surface, with floor half-width
/// `floor` (riverFloor): the channel is a parabolic bed of the given depth for d < width/2
/// (flatter where hasFlatBed()), scaled by how well the samples resolve it (0 up to a channel
/// half-width of `floor`, whole from twice that), then flat water level out to the floor's
/// edge max(width/2, floor), then banks rising with the type's bankSlope(). Evaluation
/// repeats these operations in its vector kernels (core/construction
/// evaluation_kernels.inc), tested against this definition.
inline double riverProfile(RiverType type, double width, double depth, double d,
                           double floor = 0.0) noexcept {
  const double half = 0.5 * width;
  const double edge = std::max(half, floor);
  if (d < half) {
    const double resolved = std::clamp(half * riverFloorInverse(floor) - 1.0, 0.0, 1.0);
    const double t2 = (d / half) * (d / half);
    return -depth * resolved * (1.0 - (hasFlatBed(type) ? t2 * t2 : t2));
  }
  return d < edge ? 0.0 : bankSlope(type) * (d - edge);
}

/// The weight of a river's sample d metres from its curve: falloff (1 − e²/(r − f)²)² of the
/// distance e = max(d − f, 0) beyond the floor's edge f = max(width/2, floor), times the LOD
/// fade (riverFade), so the floor keeps weight `fade` (1 where the river is whole: no other
/// relief mixes into it) and the support still ends at the radius.
inline double riverWeight(double width, double radius, double d, double floor = 0.0,
                          double fade = 1.0) noexcept {
  const double edge = std::max(0.5 * width, floor);
  const double e = std::max(d - edge, 0.0);
  return falloff(e * e, (radius - edge) * (radius - edge)) * fade;
}

/// One river primitive per edge (node → parent), in node order (mouths have none), built
/// as Section 7.1 describes: tributaries bend to meet the main stem at a node at a right
/// angle when their Strahler numbers differ and at 45° when they are equal. Each curve follows
/// a smooth valley path (meander_curve.h: ValleyPath) whose tangent at a node is shared with the
/// curves of the main stem through it (centripetal Catmull-Rom through the main inflow, the node
/// and its parent), so chains of edges join without corners. Along it, E channels meander in
/// whole sine-generated waves (Langbein & Leopold 1966; ω 1.3–1.6 rad, sinuosity 1.6–2.2,
/// wavelengths 10–14 channel widths down the valley, at least 200 m), B channels barely
/// (ω 0.1–0.25 rad), D channels get their braided jitter and deltas run along the path; points
/// turn by at most ~20° from one to the next and lie at most 50 m apart. u_z falls linearly with
/// arc length from the upstream node to the downstream node, and width and depth vary from the
/// upstream node's flow to the downstream node's, so sections agree where they meet. Curve
/// points keep half of δ from the shore of `land` (or as much as their straight edge does):
/// bends that come nearer are tamed as a whole first. The section between two consecutive chain
/// nodes of a drawn river of `features` (recognised by their stored positions:
/// network::drawnCourse's chain points, quantized) is the drawn line between them instead, every
/// vertex kept, points at most 50 m apart, not perturbed.
std::vector<RiverPrimitive> generateRiverPrimitives(const input::Params& params,
                                                    const network::RiverNetwork& network,
                                                    const analysis::NetworkAnalysis& analysis,
                                                    const geometry::PolygonIndex& land,
                                                    const input::Features& features = {});

} // namespace strahler::primitives
