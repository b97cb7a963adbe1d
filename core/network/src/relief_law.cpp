#include "strahler/network/relief_law.h"

#include <algorithm>

namespace strahler::network {
namespace {
constexpr double kRangeWavelength = 15000.0; // metres, scale of mountain ranges and plains
constexpr std::uint64_t kReliefStream = 0x72656c696566ull;

double smoothstep(double t) noexcept {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
} // namespace

ReliefLaw::ReliefLaw(const input::WorldSpec& spec, const geometry::PolygonIndex& land)
    : spec_(spec), land_(land), noise_(spec.params.seed ^ kReliefStream) {}

double ReliefLaw::mountainousness(geometry::Vec2 p) const noexcept {
  if (auto v = spec_.constraintAt(input::ConstraintKind::kMountainousness, p))
    return std::clamp(*v, 0.0, 1.0);
  const double ramp = spec_.params.coastRamp;
  const double coast = smoothstep(land_.distanceToBoundary(p, ramp) / ramp);
  const double ranges =
      0.5 + 0.5 * std::clamp(noise_.fbm(p / kRangeWavelength, 3) * 1.6, -1.0, 1.0);
  return coast * (0.25 + 0.75 * ranges);
}

double ReliefLaw::riverSlope(geometry::Vec2 p) const noexcept {
  const input::Params& params = spec_.params;
  double t;
  if (auto v = spec_.constraintAt(input::ConstraintKind::kRiverSlope, p))
    t = std::clamp(*v, 0.0, 1.0);
  else
    t = mountainousness(p);
  return params.slopeMin + (params.slopeMax - params.slopeMin) * t;
}

double ReliefLaw::ridgeLambda(geometry::Vec2 p) const noexcept {
  const input::Params& params = spec_.params;
  return params.lambda *
         (params.lambdaCoastFactor + (1.0 - params.lambdaCoastFactor) * mountainousness(p));
}

} // namespace strahler::network
