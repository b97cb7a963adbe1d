#pragma once

#include "strahler/geometry/vec2.h"

#include <span>
#include <vector>

namespace strahler::render {

/// One isoline of a height grid.
struct ContourLine {
  double elevation = 0.0;             ///< Its level, m.
  std::vector<geometry::Vec2> points; ///< Grid coordinates (column, row), ≥ 2 points.
  bool closed = false;                ///< A loop: its last point joins its first.
};

/// The levels that are multiples of `interval` (> 0) in (lo, hi], ascending.
std::vector<double> contourLevels(double lo, double hi, double interval);

/// The isolines of `heights` (width × height samples, row-major, row 0 first) at each of
/// `levels` (ascending), by marching squares (saddles decided by the cell's mean) with the segments
/// joined into lines. A sample at or above a level counts as above it. A crossing point depends
/// only on the two samples of its grid edge, so two grids that share a row or column of samples
/// cross it at the same points.
std::vector<ContourLine> traceContours(std::span<const double> heights, int width, int height,
                                       std::span<const double> levels);

} // namespace strahler::render
