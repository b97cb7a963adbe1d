#pragma once

#include "strahler/geometry/vec2.h"
#include "strahler/vector_tile/vector_tile.h"

#include <span>
#include <vector>

namespace strahler::vector_tile {

/// The square [lo, hi]² of tile coordinates a tile keeps: its extent plus a buffer.
struct ClipBox {
  double lo = 0.0; ///< West and north edge (−buffer).
  double hi = 0.0; ///< East and south edge (extent + buffer).

  /// True when `p` is inside or on the box.
  bool contains(geometry::Vec2 p) const noexcept {
    return p.x >= lo && p.x <= hi && p.y >= lo && p.y <= hi;
  }
};

/// The pieces of `line` inside `box` (Liang–Barsky per segment, consecutive pieces joined).
std::vector<std::vector<geometry::Vec2>> clipLine(std::span<const geometry::Vec2> line,
                                                  const ClipBox& box);

/// `ring` (closing point implicit) clipped to `box` by Sutherland–Hodgman: one ring that may
/// run along the box's edges where the polygon leaves it; empty when nothing is inside.
std::vector<geometry::Vec2> clipRing(std::span<const geometry::Vec2> ring, const ClipBox& box);

/// Twice the signed area of `ring` by the surveyor's formula (positive: clockwise with y down).
double ringArea2(std::span<const geometry::Vec2> ring) noexcept;

/// `line` simplified by Douglas–Peucker within `tolerance` tile units, rounded to integers,
/// consecutive repeats dropped. A ring is treated as a line that returns to its first point.
std::vector<Point> toTilePoints(std::span<const geometry::Vec2> line, double tolerance, bool ring);

} // namespace strahler::vector_tile
