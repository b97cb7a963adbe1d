#pragma once

#include "strahler/base/result.h"
#include "strahler/base/stage_timer.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/input/world_spec.h"
#include "strahler/network/mouth_placement.h"
#include "strahler/network/river_network.h"

#include <vector>

namespace strahler::network {

/// Grows the river trees from `mouths` with the open grammar of Section 4.2:
/// - selection: among candidates within ζ metres of the lowest one, the highest priority
///   (ties: the lowest, then the oldest);
/// - rules: 2.1 prolongation (Pc), 2.2 asymmetric branching (Pa), 2.3 symmetric branching
///   (Ps); once every candidate has priority 1, rule 1 (fill): fillBranches (≤ 2) children, so
///   no node has more than two children (binary confluences);
/// - a child is kept only if it is in Ω, its edge stays more than δ from Γ, more than σ from
///   every non-adjacent edge, and its slope to nearby nodes is below κ (a few angles are
///   tried per child before it is rejected);
/// - every child is higher than its parent by the ReliefLaw's slope times e;
/// - once no candidate is left, growth goes back to the gaps: land farther than 2.4 km from
///   every edge gets a child of a nearby node (one with at most one child) aimed at it, or a
///   new mouth at a nearby shore site (shoreSites), and growth resumes (a few rounds), so
///   every land point lies within 3 km of a river on the worlds measured
///   (docs/architecture.md).
/// Strahler numbers are computed on the final trees. Deterministic for a given spec.
base::Result<RiverNetwork> growNetwork(const input::WorldSpec& spec,
                                       const geometry::PolygonIndex& land,
                                       const std::vector<MouthSite>& mouths,
                                       const base::ProgressCallback& progress = {});

/// placeMouths followed by the grower of spec.params.grower: growNetwork (the grammar) or
/// growNetworkDla (dla_growth.h).
base::Result<RiverNetwork> generateNetwork(const input::WorldSpec& spec,
                                           const geometry::PolygonIndex& land,
                                           const base::ProgressCallback& progress = {});

} // namespace strahler::network
