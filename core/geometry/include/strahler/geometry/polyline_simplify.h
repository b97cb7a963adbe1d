#pragma once

#include "strahler/geometry/vec2.h"

#include <cstddef>
#include <span>
#include <vector>

namespace strahler::geometry {

/// Douglas–Peucker simplification: the indices (ascending) of the points of `points` to keep
/// so that every dropped point lies within `tolerance` (≥ 0, same units) of the kept polyline
/// between its kept neighbours. The first and last points are always kept; fewer than 3
/// points are all kept.
std::vector<std::size_t> simplifyPolyline(std::span<const Vec2> points, double tolerance);

} // namespace strahler::geometry
