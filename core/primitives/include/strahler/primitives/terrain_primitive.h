#pragma once

#include "strahler/geometry/vec2.h"

namespace strahler::primitives {

/// Terrain primitive T (Section 6.1): a disc of influence with a base elevation and noise.
/// h(p) = elevation + amplitude · n(p), w(p) = (1 − d²/r²)² for d < r, else 0, where n is
/// the world's shared fBm noise with gain `roughness`. Blending many primitives blends their
/// elevations and their noise parameters (amplitude, roughness) and adds one shared noise, so
/// the noise stays coherent instead of averaging away (construction::World).
struct TerrainPrimitive {
  geometry::Vec2 center;  ///< c, local metres.
  double radius = 0.0;    ///< r, metres.
  double elevation = 0.0; ///< c_z, metres (Section 7.2 interpolation).
  double amplitude = 0.0; ///< Noise amplitude, metres (rough mountains, smooth plains).
  double roughness = 0.5; ///< fBm gain per octave, in [0.3, 0.7].

  friend bool operator==(const TerrainPrimitive&, const TerrainPrimitive&) = default;
};

/// Falloff (1 − d²/r²)² of every primitive, given d² and r² (0 outside the support).
inline double falloff(double distanceSquared, double radiusSquared) noexcept {
  if (distanceSquared >= radiusSquared)
    return 0.0;
  const double t = 1.0 - distanceSquared / radiusSquared;
  return t * t;
}

} // namespace strahler::primitives
