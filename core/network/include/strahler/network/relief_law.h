#pragma once

#include "strahler/geometry/polygon_index.h"
#include "strahler/input/world_spec.h"
#include "strahler/noise/gradient_noise.h"

namespace strahler::network {

/// The mountainousness field m(p) ∈ [0, 1] and the river-slope law derived from it.
/// Without a constraint image, m rises from 0 at the coast to 1 at `coastRamp` inland and is
/// modulated by low-frequency noise (wavelength ~15 km) so that ranges and plains appear;
/// a mountainousness image replaces it, a river-slope image sets the slope directly.
class ReliefLaw {
public:
  /// Law for `spec`; `land` must outlive this object.
  ReliefLaw(const input::WorldSpec& spec, const geometry::PolygonIndex& land);

  /// m(p) ∈ [0, 1] at a local point.
  double mountainousness(geometry::Vec2 p) const noexcept;
  /// Mean river slope (m/m) at p, in [slopeMin, slopeMax].
  double riverSlope(geometry::Vec2 p) const noexcept;
  /// λ at p (Section 5.1): lambda · (lambdaCoastFactor + (1 − lambdaCoastFactor) · m(p)).
  double ridgeLambda(geometry::Vec2 p) const noexcept;

private:
  const input::WorldSpec& spec_;
  const geometry::PolygonIndex& land_;
  noise::GradientNoise noise_;
};

} // namespace strahler::network
