#include "strahler/geometry/projection.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::geometry {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

LocalProjection::LocalProjection(double lon0, double lat0) noexcept
    : lon0_(lon0), lat0_(lat0), sinLat0_(std::sin(lat0 * kDeg)), cosLat0_(std::cos(lat0 * kDeg)) {}

Vec2 LocalProjection::forward(Vec2 lonLat) const noexcept {
  const double lambda = (lonLat.x - lon0_) * kDeg;
  const double phi = lonLat.y * kDeg;
  const double sinPhi = std::sin(phi), cosPhi = std::cos(phi);
  const double cosLambda = std::cos(lambda);
  const double denom = 1.0 + sinLat0_ * sinPhi + cosLat0_ * cosPhi * cosLambda;
  const double k = std::sqrt(2.0 / std::max(denom, 1e-300));
  return {kEarthRadius * k * cosPhi * std::sin(lambda),
          kEarthRadius * k * (cosLat0_ * sinPhi - sinLat0_ * cosPhi * cosLambda)};
}

Vec2 LocalProjection::inverse(Vec2 xy) const noexcept {
  const double rho = std::hypot(xy.x, xy.y);
  if (rho == 0.0)
    return {lon0_, lat0_};
  const double c = 2.0 * std::asin(std::min(1.0, rho / (2.0 * kEarthRadius)));
  const double sinC = std::sin(c), cosC = std::cos(c);
  const double phi =
      std::asin(std::clamp(cosC * sinLat0_ + xy.y * sinC * cosLat0_ / rho, -1.0, 1.0));
  const double lambda = std::atan2(xy.x * sinC, rho * cosLat0_ * cosC - xy.y * sinLat0_ * sinC);
  return {lon0_ + lambda / kDeg, phi / kDeg};
}

} // namespace strahler::geometry
