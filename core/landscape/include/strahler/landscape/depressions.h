#pragma once

#include "strahler/landscape/lattice_grid.h"

#include <cstdint>

namespace strahler::landscape {

/// What a lattice node is to the evolution.
enum class NodeRole : std::uint8_t {
  kFree = 0,      ///< Land that erodes.
  kBaseLevel = 1, ///< Sea, lakes and the lattice's edge: water leaves here, height fixed.
  kPinned = 2,    ///< A river of the graph crosses it: base level too, height fixed.
};

/// Fills every depression of `heights` (priority-flood with an epsilon gradient, Barnes,
/// Lehman & Mulla 2014): afterwards every free node has a path to a base-level or pinned node
/// along which heights strictly fall, by at least `epsilon` per step, through edge neighbours
/// (four-connected: a surface interpolated between the nodes then drains too, where a diagonal
/// path would be dammed by the two nodes beside it). Fixed nodes keep their height.
/// Deterministic (ties broken by index).
void fillDepressions(LatticeGrid<double>& heights, const LatticeGrid<NodeRole>& roles,
                     double epsilon);

} // namespace strahler::landscape
