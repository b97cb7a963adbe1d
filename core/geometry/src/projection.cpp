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

void LocalProjection::forwardGrid(const std::vector<double>& lons, const std::vector<double>& lats,
                                  std::vector<Vec2>& out) const {
  std::vector<double> sinLambda(lons.size()), cosLambda(lons.size());
  for (std::size_t i = 0; i < lons.size(); ++i) {
    const double lambda = (lons[i] - lon0_) * kDeg;
    sinLambda[i] = std::sin(lambda);
    cosLambda[i] = std::cos(lambda);
  }
  out.resize(lons.size() * lats.size());
  for (std::size_t j = 0; j < lats.size(); ++j) {
    const double phi = lats[j] * kDeg;
    const double sinPhi = std::sin(phi), cosPhi = std::cos(phi);
    for (std::size_t i = 0; i < lons.size(); ++i) {
      const double denom = 1.0 + sinLat0_ * sinPhi + cosLat0_ * cosPhi * cosLambda[i];
      const double k = std::sqrt(2.0 / std::max(denom, 1e-300));
      out[j * lons.size() + i] = {kEarthRadius * k * cosPhi * sinLambda[i],
                                  kEarthRadius * k *
                                      (cosLat0_ * sinPhi - sinLat0_ * cosPhi * cosLambda[i])};
    }
  }
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
