#pragma once

#include "strahler/construction/world_data.h"
#include "strahler/geometry/vec2.h"
#include "strahler/primitives/river_primitive.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace strahler::render {

/// A river section: a run of network edges with the same Strahler order and Rosgen type,
/// following the curves of its river primitives (the carved channels, meanders included).
struct RiverSection {
  std::vector<geometry::Vec2> line; ///< Local metres, upstream first, not simplified.
  int strahler = 1;                 ///< Horton–Strahler order.
  std::uint32_t tree = 0;           ///< Index of its tree (of its mouth).
  primitives::RiverType rosgen = primitives::RiverType::kStraight; ///< Its Rosgen type.
  double flow = 0.0;                                               ///< m³/s at its downstream end.
  double widthUp = 0.0;       ///< Channel width at its upstream end, m.
  double widthDown = 0.0;     ///< Channel width at its downstream end, m.
  double elevationUp = 0.0;   ///< Elevation of its upstream node, m.
  double elevationDown = 0.0; ///< Elevation of its downstream node, m.
};

/// Calls `visit` with each river section of `world`, in the order of their upstream nodes. A
/// section without primitives (a world whose rivers do not match its network) follows its
/// straight edges. The section passed is valid during the call only.
void forEachRiverSection(const construction::WorldData& world,
                         const std::function<void(const RiverSection&)>& visit);

} // namespace strahler::render
