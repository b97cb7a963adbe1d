#pragma once

#include "strahler/geometry/vec2.h"

#include <cmath>

namespace strahler::primitives {

/// Storage precision of every value of a world. The generator snaps its output to these
/// steps and the world file stores integer multiples of them, so a world survives a save
/// and load bit for bit: a value v is stored as k = llround(v / step) and read as k · step.
struct Quantum {
  static constexpr double kPosition = 0.125; ///< Metres: positions, lengths along the ground.
  static constexpr double kElevation = 0.01; ///< Metres: elevations, depths, amplitudes.
  static constexpr double kRadius = 0.125;   ///< Metres: radii and widths.
  static constexpr double kRoughness = 1.0 / 1024.0; ///< fBm gain.
  static constexpr double kFlow = 0.001;             ///< m³/s.
  static constexpr double kSlope = 1.0 / 4096.0;     ///< Metres per metre: gradients.
};

/// v snapped to a multiple of `step` (computed as the file reader does: k · step).
inline double quantize(double v, double step) noexcept {
  return static_cast<double>(std::llround(v / step)) * step;
}

/// A point snapped to the position grid.
inline geometry::Vec2 quantize(geometry::Vec2 p) noexcept {
  return {quantize(p.x, Quantum::kPosition), quantize(p.y, Quantum::kPosition)};
}

} // namespace strahler::primitives
