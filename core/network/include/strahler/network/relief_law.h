#pragma once

#include "strahler/geometry/polygon_index.h"
#include "strahler/input/features.h"
#include "strahler/input/world_spec.h"
#include "strahler/noise/gradient_noise.h"

#include <vector>

namespace strahler::network {

/// Radius (m) of a drawn mountain's slopes: its `radius` when given; else 4 × its `elevation`
/// (a mean slope of 1 in 4 from the summit to the foot); else 5 % of the square root of the
/// land area (the map's scale); the last two clamped to [1 km, 15 km].
double mountainRadius(const input::MountainFeature& mountain, double landAreaM2) noexcept;
/// Half-width (m) of the range along a drawn ridgeline: 2 × its `elevation` when given, else
/// 3 % of the square root of the land area, clamped to [1 km, 8 km].
double ridgeHalfWidth(const input::RidgeFeature& ridge, double landAreaM2) noexcept;
/// Distance (m) from p to a polyline and the nearest point on it (infinite for < 2 points).
struct LineHit {
  double distance = 0.0; ///< m.
  geometry::Vec2 point;  ///< Nearest point of the line.
};
/// The nearest point of `line` to p.
LineHit nearestOnLine(const std::vector<geometry::Vec2>& line, geometry::Vec2 p) noexcept;

/// The mountainousness field m(p) ∈ [0, 1] and the river-slope law derived from it.
/// Without a constraint image, m rises from 0 at the coast to 1 at `coastRamp` inland and is
/// modulated by low-frequency noise (wavelength ~15 km) so that ranges and plains appear;
/// a mountainousness image replaces it, a river-slope image sets the slope directly.
/// With drawn mountains or ridgelines (spec.features, no image), they give m as the paper's
/// image would: m = max(m₀, coast · drawn), m₀ the field above (unchanged away from them) and
/// drawn = 1 within half a mountain's radius (half a ridge's half-width), fading smoothly to 0
/// at its radius (half-width).
class ReliefLaw {
public:
  /// Law for `spec`; `spec` and `land` must outlive this object.
  ReliefLaw(const input::WorldSpec& spec, const geometry::PolygonIndex& land);

  /// m(p) ∈ [0, 1] at a local point.
  double mountainousness(geometry::Vec2 p) const noexcept;
  /// Mean river slope (m/m) at p, in [slopeMin, slopeMax].
  double riverSlope(geometry::Vec2 p) const noexcept;
  /// λ at p (Section 5.1): lambda · (lambdaCoastFactor + (1 − lambdaCoastFactor) · m(p)).
  double ridgeLambda(geometry::Vec2 p) const noexcept;
  /// How much the drawn mountains and ridgelines hold p, in [0, 1] (0 without features).
  double drawnMountainousness(geometry::Vec2 p) const noexcept;
  /// Land area of the spec, m² (computed only when features are drawn, else 0).
  double landAreaM2() const noexcept { return landArea_; }

private:
  const input::WorldSpec& spec_;
  const geometry::PolygonIndex& land_;
  noise::GradientNoise noise_;
  double landArea_ = 0.0;
  std::vector<double> mountainRadii_; ///< Per drawn mountain, m.
  std::vector<double> ridgeWidths_;   ///< Per drawn ridge: half-width, m.
};

} // namespace strahler::network
