#pragma once
// Private to core/repair: a ring split into simple loops where it crosses or touches itself.

#include "strahler/base/result.h"
#include "strahler/geometry/polygon.h"

#include <cstdint>
#include <vector>

namespace strahler::repair::detail {

/// A point where two segments of a ring meet (other than consecutive segments at their
/// shared vertex). Segment k runs from vertex k to vertex k + 1 of the ring it was found in.
struct Crossing {
  geometry::Vec2 point;
  std::uint32_t first = 0;  ///< The lower segment index.
  std::uint32_t second = 0; ///< The higher one.
  bool touch = false;       ///< At a vertex of either segment (touching), not a proper crossing.
};

/// One simple closed piece of a ring, in the ring's order, without the closing vertex.
struct Loop {
  geometry::Ring vertices;
  double signedArea = 0.0; ///< Degrees², positive when counter-clockwise.
  int crossing = -1;       ///< Index into SplitRing::crossings where it was cut off; -1: the rest.
};

/// A ring cut at every self-intersection into loops, none of which crosses or touches itself.
/// Loops of zero area (the two sides of a stretch the ring runs twice) are set apart.
struct SplitRing {
  std::vector<Crossing> crossings; ///< Distinct points, in the order of their first segment.
  std::vector<Loop> loops;
  std::vector<Loop> flat; ///< Loops left out for having no area (a stretch run twice).
};

/// Finds where the segments of `ring` (without duplicate consecutive vertices) cross or touch
/// (Boost.Geometry's segment intersection, an R-tree of segment boxes), inserts those points
/// into both segments, and walks the ring cutting off a loop each time it returns to a point
/// it has passed. Intersection points closer than about 1e-9 degrees are merged. More than
/// `maxCrossings` points: kLimitExceeded.
base::Result<SplitRing> splitRing(const geometry::Ring& ring, std::size_t maxCrossings);

} // namespace strahler::repair::detail
