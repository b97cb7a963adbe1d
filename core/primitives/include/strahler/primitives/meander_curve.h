#pragma once

#include "strahler/geometry/vec2.h"

#include <functional>
#include <vector>

namespace strahler::primitives {

/// The smooth axis a river section's curve follows from one node to the next: a cubic Bézier
/// leaving `from` along the unit tangent `leave` and arriving at `to` along the unit tangent
/// `arrive`, its arms `arm` thirds of the chord (default one third). Consecutive sections that
/// share the tangent at their common node join without a corner.
class ValleyPath {
public:
  ValleyPath(geometry::Vec2 from, geometry::Vec2 leave, geometry::Vec2 to, geometry::Vec2 arrive,
             double arm = 1.0);

  /// The same ends and tangents with arms `arm` thirds of the chord: nearer the chord for arm < 1.
  ValleyPath withArms(double arm) const;

  /// Arc length of the path, m.
  double length() const noexcept { return arc_.back(); }
  /// The point `x` metres along the path (beyond its ends: along the end tangents).
  geometry::Vec2 at(double x) const noexcept;
  /// The unit tangent `x` metres along the path.
  geometry::Vec2 tangent(double x) const noexcept;

private:
  double parameterAt(double x) const noexcept;
  geometry::Vec2 control_[4];
  geometry::Vec2 leave_, arrive_;
  std::vector<double> arc_; ///< Arc length at parameters k / (size − 1).
};

/// One wave of a sine-generated meander (Langbein & Leopold 1966): over the wave, the channel's
/// direction deviates from the valley's by θ = ω sin φ − f ω³ sin 3φ, φ from 0 to 2π uniformly
/// along the channel's arc (f: Kinoshita's flattening). A whole wave starts and ends heading
/// along the valley and returns to the valley's axis.
struct MeanderWave {
  double omega = 0.0;      ///< ω: largest deflection, radians (negative: first bend right).
  double flattening = 0.0; ///< f: flattening coefficient, ≥ 0 (0: a pure sine-generated wave).
  double length = 1.0;     ///< Relative arc length of this wave among the section's waves, > 0.
};

/// Sinuosity of one wave (channel length over valley length): 1 / J0(ω) without flattening.
double meanderSinuosity(const MeanderWave& wave) noexcept;

/// How finely a curve is cut into points.
struct CurveSampling {
  double maxTurn = 0.35; ///< Largest change of direction between consecutive points, radians.
  double maxStep = 50.0; ///< Largest distance between consecutive points, m.
};

/// The points of a channel following `valley` through `waves` whole meander waves, fitted to the
/// valley's length (scaled, so the channel starts and ends exactly at the valley's ends heading
/// along it), lateral offsets laid along the valley's normal. Points are spaced by `sampling`,
/// more closely in the tight bends. No waves: the valley path itself. `shift`, if given, moves
/// the channel sideways by shift(x) metres x along the valley (0 and flat at both ends).
std::vector<geometry::Vec2> meanderCurve(const ValleyPath& valley,
                                         const std::vector<MeanderWave>& waves,
                                         const CurveSampling& sampling,
                                         const std::function<double(double)>& shift = {});

} // namespace strahler::primitives
