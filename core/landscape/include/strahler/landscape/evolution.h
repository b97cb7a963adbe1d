#pragma once

#include "strahler/base/stage_timer.h"
#include "strahler/landscape/depressions.h"
#include "strahler/landscape/lattice_grid.h"

#include <cstdint>

namespace strahler::landscape {

/// The knobs of the landscape evolution, in steps of one unit of time on a lattice of
/// `spacing` metres. Heights in metres, drainage area in m².
struct EvolutionParams {
  double spacing = 60.0;        ///< Lattice spacing, m.
  int steps = 20;               ///< Time steps.
  double areaExponent = 0.45;   ///< m of stream power E = K A^m S (n = 1).
  double incision = 0.2;        ///< K, per step, m^(1 − 2m), times each node's erodibility.
  double channelArea = 0.0;     ///< m²: incision × (1 − channelArea / A)⁺ (channel heads).
  double restoring = 0.02;      ///< Pull toward the tree's height per step (the uplift).
  double diffusivity = 0.1;     ///< D·dt / spacing² per step, times each node's diffusivity.
  double criticalSlope = 1.0;   ///< S_c of the nonlinear hillslope flux (Roering et al. 1999).
  double routingExponent = 1.0; ///< Receivers drawn with probability ∝ slope^this.
  std::uint64_t seed = 0;       ///< Seeds the receivers' draws.
  int threads = 0;              ///< Threads of the row-parallel stages; 0: the cores (at most 8).
};

/// What the evolution starts from. Every grid has the same size.
struct EvolutionInput {
  LatticeGrid<double> tree;       ///< The construction tree's heights: start and uplift target.
  LatticeGrid<NodeRole> roles;    ///< Which nodes erode and which are fixed base levels.
  LatticeGrid<float> erodibility; ///< Multiplier of EvolutionParams::incision, > 0.
  LatticeGrid<float> diffusivity; ///< Multiplier of EvolutionParams::diffusivity, ≥ 0.
};

/// What the evolution ends with.
struct EvolutionResult {
  LatticeGrid<double> heights; ///< Eroded heights; fixed nodes keep the tree's.
  LatticeGrid<float> area;     ///< Drainage area of the last step, m².
};

/// Runs the landscape evolution: depressions filled, then per step receivers drawn among the
/// lower neighbours with probability ∝ slope^routingExponent from a hash of (seed, step,
/// node) (jittered single-direction routing: the drainage of many steps spreads as multiple-
/// direction routing does, without D8's comb), drainage area down the receiver tree, stream
/// power with the restoring uplift solved implicitly up the tree (Braun & Willett 2013),
/// then nonlinear hillslope transport (flux D·S / (1 − (S/S_c)²), explicit, capped stable).
/// Deterministic: a pure function of its arguments. `progress` gets ("erosion", fraction).
EvolutionResult evolveLandscape(const EvolutionInput& input, const EvolutionParams& params,
                                const base::ProgressCallback& progress = {});

} // namespace strahler::landscape
