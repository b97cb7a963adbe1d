#pragma once

#include "strahler/base/result.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/input/world_spec.h"

#include <vector>

namespace strahler::network {

/// A place on the shore where a river tree starts.
struct MouthSite {
  geometry::Vec2 position;    ///< On the coast or a lake shore, local metres.
  geometry::Vec2 inward;      ///< Unit vector into the land.
  int priority = 1;           ///< Grammar priority index s of the tree's root.
  bool onLake = false;        ///< On a polygon hole (lake) rather than the sea coast.
  double accessibility = 0.0; ///< Land fraction within accessibilityRadius (concavity).
  int drawnRiver = -1;        ///< Index of the drawn river it is the mouth of; -1: none.
};

/// Places mouths along Γ (Section 4.1): the shore is sampled every e/2, each sample scored by
/// its accessibility (fraction of land within accessibilityRadius: bays score high), samples
/// whose first edge could not grow are dropped, then the best are taken greedily at least
/// mouthSpacing apart, and every island that can hold a river gets one. Priorities follow
/// the rank like Strahler orders: the best mouth gets maxPriority, the next two one less,
/// the next four one less again, and so on; lake mouths get priority 1. Mouths whose inward
/// normal points within 30° of a drawn mountain (spec.features.mountains) rank before the
/// others, so the trees that drain the ranges grow the longest trunks.
/// Drawn rivers (spec.features.rivers) put their mouths first, at the line's last point
/// snapped to the shore (drawnCourse), with priority maxPriority; placed or user mouths within
/// mouthSpacing of a drawn mouth, or within σ of a drawn river, are left out.
/// User mouths in `spec` replace all this: each is snapped to the nearest shore point
/// (kInvalidInput if none lies within 5 km).
base::Result<std::vector<MouthSite>> placeMouths(const input::WorldSpec& spec,
                                                 const geometry::PolygonIndex& land);

/// Every place on the shore where a river could start: Γ sampled every e/2 with the inward
/// normal of the shore over ±e, kept where a first edge straight inland would be valid
/// (priority 1, accessibility left 0). Growth takes its gap mouths from these.
std::vector<MouthSite> shoreSites(const input::Params& params, const geometry::PolygonIndex& land);

} // namespace strahler::network
