#pragma once

#include "strahler/base/result.h"
#include "strahler/base/stage_timer.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/input/world_spec.h"
#include "strahler/network/mouth_placement.h"
#include "strahler/network/river_network.h"

#include <vector>

namespace strahler::network {

/// Grows the river trees from `mouths` by off-lattice diffusion-limited aggregation (seed 001,
/// after Masek & Turcotte 1993), the alternative to growNetwork's grammar:
/// - particles are launched one by one at random land points farther than e from the network
///   and walk at any angle (steps as long as the distance to the nearest node allows, found
///   in a grid hash), staying in Ω, until they come within e of a node;
/// - there they stick with a probability that grows with the cosine between the new edge and
///   the node's preferred direction (its own flow direction, bent up the gradient of the
///   mountainousness m, so a constraint map or drawn mountains steer the growth), and attach as
///   a child of the nearest node that has fewer than two children, at distance e, its direction
///   turned back into the grammar's cone (at most branchAngle + angleJitter from the node's own
///   flow direction) and more than 0.6 branchAngle from a sibling's;
/// - a new edge obeys the grammar's rules (in Ω, more than δ from Γ, more than σ from every
///   non-adjacent edge, slopes below κ, clear of ridgelines and drawn rivers); a particle
///   whose edge breaks them is dropped;
/// - drawn rivers are placed first as chains of nodes (as the grammar does), lakes and user
///   mouths come with `mouths`;
/// - growth runs to saturation (bounded: at most 40 particles per expected node, and 4000
///   steps per walk), then first-order twigs of a single edge are pruned off nodes of higher
///   order where another river passes within 1.5 e of their tip, which leaves slender
///   branches without opening gaps;
/// - every child is higher than its parent by the ReliefLaw's slope times e; a node's
///   priority is its Strahler number.
/// Deterministic for a given spec (one seeded random stream, single-threaded).
base::Result<RiverNetwork> growNetworkDla(const input::WorldSpec& spec,
                                          const geometry::PolygonIndex& land,
                                          const std::vector<MouthSite>& mouths,
                                          const base::ProgressCallback& progress = {});

} // namespace strahler::network
