#pragma once

#include "strahler/geometry/vec2.h"

namespace strahler::primitives {

/// Terrain primitive T (Section 6.1): a disc of influence with a sloping plane and noise.
/// h(p) = elevation + slope · (p − center) + Σ_k amplitude · roughness^k · octave_k(p),
/// w(p) = (1 − d²/r²)² for d < r, else 0, where the octaves are the world's shared relief octaves
/// (gullies down the slope, then gradient noise). Blending many primitives blends their elevations
/// and their relief parameters (amplitude, roughness) and adds one shared relief, so it stays
/// coherent instead of averaging away (construction::World).
struct TerrainPrimitive {
  geometry::Vec2 center;  ///< c, local metres.
  double radius = 0.0;    ///< r, metres.
  double elevation = 0.0; ///< c_z, metres (Section 7.2 interpolation).
  /// Gradient of the primitive's plane, m/m: the hillslope it lies on, so that a blend of
  /// primitives keeps the slopes from the rivers up to the ridges instead of averaging them
  /// into plateaus.
  geometry::Vec2 slope{};
  double amplitude = 0.0; ///< Relief amplitude, metres (rough mountains, smooth plains).
  double roughness = 0.5; ///< Gain per octave, in [0.3, 0.7].

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
