#pragma once

#include "strahler/analysis/network_analysis.h"
#include "strahler/input/params.h"
#include "strahler/network/river_network.h"
#include "strahler/primitives/river_primitive.h"

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

/// The profile δ(d) across a river, relative to its water surface: a parabolic bed of the
/// given depth for d < width/2 (flatter where hasFlatBed()), then banks rising with the
/// type's bankSlope(). Evaluation repeats these operations in its vector kernels
/// (core/construction evaluation_kernels.inc), tested against this definition.
inline double riverProfile(RiverType type, double width, double depth, double d) noexcept {
  const double half = 0.5 * width;
  if (d < half) {
    const double t2 = (d / half) * (d / half);
    return -depth * (1.0 - (hasFlatBed(type) ? t2 * t2 : t2));
  }
  return bankSlope(type) * (d - half);
}

/// One river primitive per edge (node → parent), in node order (mouths have none), built
/// as Section 7.1 describes: tributaries bend to meet the main stem at a node at a right
/// angle when their Strahler numbers differ and at 45° when they are equal; curves are
/// smoothed, subdivided below 50 m and perturbed by type (B nearly straight, E meanders of
/// wavelength ~11 widths, D braided jitter, deltas straight); u_z falls linearly with arc
/// length from the upstream node to the downstream node, and width and depth vary from the
/// upstream node's flow to the downstream node's, so sections agree where they meet.
std::vector<RiverPrimitive> generateRiverPrimitives(const input::Params& params,
                                                    const network::RiverNetwork& network,
                                                    const analysis::NetworkAnalysis& analysis);

} // namespace strahler::primitives
