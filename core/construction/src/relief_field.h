#pragma once

#include "strahler/construction/world_data.h"
#include "strahler/geometry/vec2.h"

#include <cstdint>
#include <vector>

namespace strahler::construction::detail {

/// The erosion's residual as evaluation reads it: a pyramid of the stored lattice (level k
/// every spacing · 2^k metres, each level the tent-filtered level below), interpolated by
/// Catmull-Rom splines (C¹: no facets) at the level whose nodes are no farther apart than the
/// samples asked for, so coarse samples read a prefiltered field instead of aliasing it.
class ReliefField {
public:
  /// The pyramid of `residual` (which must not be empty).
  explicit ReliefField(const ReliefResidual& residual);

  /// Δh (m) at local point p for samples `spacing` metres apart; 0 outside the lattice.
  double at(geometry::Vec2 p, double spacing) const noexcept;

private:
  struct Level {
    double spacing = 0.0;     // m between nodes
    double inverse = 0.0;     // 1 / spacing
    std::int64_t column0 = 0; // global index of the first column at this level
    std::int64_t row0 = 0;
    int columns = 0;
    int rows = 0;
    std::vector<float> values; // row-major
  };
  const Level& levelFor(double spacing) const noexcept;
  static double interpolate(const Level& level, geometry::Vec2 p) noexcept;

  std::vector<Level> levels_;
};

} // namespace strahler::construction::detail
