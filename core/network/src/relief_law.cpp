#include "strahler/network/relief_law.h"

#include "strahler/base/smoothstep.h"
#include "strahler/geometry/distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strahler::network {
namespace {
constexpr double kRangeWavelength = 15000.0; // metres, scale of mountain ranges and plains
constexpr std::uint64_t kReliefStream = 0x72656c696566ull;

/// 1 within half of `reach`, 0 beyond it, smooth between.
double plateau(double distance, double reach) noexcept {
  return base::smoothstep(2.0 * (1.0 - distance / reach));
}
} // namespace

double mountainRadius(const input::MountainFeature& mountain, double landAreaM2) noexcept {
  if (mountain.radius)
    return *mountain.radius;
  const double chosen =
      mountain.elevation ? 4.0 * *mountain.elevation : 0.05 * std::sqrt(std::max(landAreaM2, 0.0));
  return std::clamp(chosen, 1000.0, 15000.0);
}

double ridgeHalfWidth(const input::RidgeFeature& ridge, double landAreaM2) noexcept {
  const double chosen =
      ridge.elevation ? 2.0 * *ridge.elevation : 0.03 * std::sqrt(std::max(landAreaM2, 0.0));
  return std::clamp(chosen, 1000.0, 8000.0);
}

LineHit nearestOnLine(const std::vector<geometry::Vec2>& line, geometry::Vec2 p) noexcept {
  LineHit best{std::numeric_limits<double>::infinity(), p};
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const geometry::Vec2 q = geometry::closestPointOnSegment(p, line[k], line[k + 1]);
    if (const double d = distance(p, q); d < best.distance)
      best = {d, q};
  }
  return best;
}

ReliefLaw::ReliefLaw(const input::WorldSpec& spec, const geometry::PolygonIndex& land)
    : spec_(spec), land_(land), noise_(spec.params.seed ^ kReliefStream) {
  const input::Features& drawn = spec.features;
  if (drawn.mountains.empty() && drawn.ridges.empty())
    return;
  landArea_ = geometry::area(spec.land);
  for (const input::MountainFeature& m : drawn.mountains)
    mountainRadii_.push_back(mountainRadius(m, landArea_));
  for (const input::RidgeFeature& r : drawn.ridges)
    ridgeWidths_.push_back(ridgeHalfWidth(r, landArea_));
}

double ReliefLaw::drawnMountainousness(geometry::Vec2 p) const noexcept {
  const input::Features& drawn = spec_.features;
  double held = 0.0;
  for (std::size_t i = 0; i < mountainRadii_.size(); ++i)
    held = std::max(held, plateau(distance(p, drawn.mountains[i].position), mountainRadii_[i]));
  for (std::size_t i = 0; i < ridgeWidths_.size() && held < 1.0; ++i)
    held =
        std::max(held, plateau(nearestOnLine(drawn.ridges[i].line, p).distance, ridgeWidths_[i]));
  return held;
}

double ReliefLaw::mountainousness(geometry::Vec2 p) const noexcept {
  if (auto v = spec_.constraintAt(input::ConstraintKind::kMountainousness, p))
    return std::clamp(*v, 0.0, 1.0);
  const double ramp = spec_.params.coastRamp;
  const double coast = base::smoothstep(land_.distanceToBoundary(p, ramp) / ramp);
  const double ranges =
      0.5 + 0.5 * std::clamp(noise_.fbm(p / kRangeWavelength, 3) * 1.6, -1.0, 1.0);
  const double undrawn = coast * (0.25 + 0.75 * ranges);
  if (mountainRadii_.empty() && ridgeWidths_.empty())
    return undrawn;
  return std::max(undrawn, coast * drawnMountainousness(p));
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
