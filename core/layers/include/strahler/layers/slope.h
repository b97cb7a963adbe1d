#pragma once

#include "strahler/layers/bordered_heights.h"

#include <vector>

namespace strahler::layers {

/// The aspect of flat ground (no direction): aspectDegrees() gives it where the gradient is 0.
inline constexpr double kFlatAspect = -1.0;

/// Slope of every pixel, degrees from horizontal (0 … 90), row-major width · height.
std::vector<double> slopeDegrees(const BorderedHeights& grid);

/// Aspect of every pixel: the compass direction the ground faces (downhill), degrees clockwise
/// from north in [0, 360), kFlatAspect where the gradient is exactly 0. Row-major.
std::vector<double> aspectDegrees(const BorderedHeights& grid);

} // namespace strahler::layers
