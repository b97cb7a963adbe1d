#pragma once

#include "strahler/geometry/vec2.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace strahler::quality {

/// Summary of checkRiversDescend.
struct RiverProfileReport {
  std::size_t samples = 0;    ///< Samples taken over all centrelines.
  std::size_t violations = 0; ///< Samples that rise more than the tolerance (see below).
  double worstRise = 0.0;     ///< Largest rise of a violation, metres; 0 without violations.
  geometry::Vec2 worstAt;     ///< Where worstRise occurs (the first such sample); local metres.
};

/// Checks that rivers never flow uphill on the terrain `height` (metres at a local point).
/// Each centreline (local metres, upstream first) is sampled at arc lengths 0, d, 2d, ... and
/// at its last point, d = sampleSpacing metres (> 0). The rise of a sample is its height minus
/// the lowest height sampled before it on the same centreline; a violation is a rise greater
/// than `tolerance` metres. A centreline of one point gives one sample and no violation.
RiverProfileReport checkRiversDescend(const std::vector<std::vector<geometry::Vec2>>& centrelines,
                                      const std::function<double(geometry::Vec2)>& height,
                                      double sampleSpacing, double tolerance);

} // namespace strahler::quality
