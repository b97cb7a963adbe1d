#include "ellipsoid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strahler::encoding::wgs84 {
namespace {

double dot(const Ecef& p, const Ecef& q) noexcept {
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}

double norm(const Ecef& p) noexcept {
  return std::sqrt(dot(p, p));
}

Ecef cross(const Ecef& p, const Ecef& q) noexcept {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}

} // namespace

SinCos SinCos::of(double radians) noexcept {
  return {std::sin(radians), std::cos(radians)};
}

Ecef toEcef(SinCos longitude, SinCos latitude, double height) noexcept {
  const double n = primeVerticalRadius(latitude);
  const double horizontal = (n + height) * latitude.cos;
  return {horizontal * longitude.cos, horizontal * longitude.sin,
          (n * (1.0 - kEccentricitySquared) + height) * latitude.sin};
}

Ecef toEcef(double longitude, double latitude, double height) noexcept {
  return toEcef(SinCos::of(longitude), SinCos::of(latitude), height);
}

Ecef geodeticUp(SinCos longitude, SinCos latitude) noexcept {
  return {latitude.cos * longitude.cos, latitude.cos * longitude.sin, latitude.sin};
}

double primeVerticalRadius(SinCos latitude) noexcept {
  return kSemiMajorAxis / std::sqrt(1.0 - kEccentricitySquared * latitude.sin * latitude.sin);
}

double meridionalRadius(SinCos latitude) noexcept {
  const double w = 1.0 - kEccentricitySquared * latitude.sin * latitude.sin;
  return kSemiMajorAxis * (1.0 - kEccentricitySquared) / (w * std::sqrt(w));
}

Sphere enclosingSphere(std::span<const Ecef> points) noexcept {
  Ecef low{}, high{};
  low.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  for (const Ecef& p : points)
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], p[k]);
      high[k] = std::max(high[k], p[k]);
    }
  Sphere sphere;
  if (points.empty())
    return sphere;
  for (int k = 0; k < 3; ++k)
    sphere.centre[k] = 0.5 * (low[k] + high[k]);
  double radiusSquared = 0.0;
  for (const Ecef& p : points) {
    const Ecef d{p[0] - sphere.centre[0], p[1] - sphere.centre[1], p[2] - sphere.centre[2]};
    radiusSquared = std::max(radiusSquared, dot(d, d));
  }
  // Rounding in the square root must never leave a point outside.
  sphere.radius = std::nextafter(std::sqrt(radiusSquared), std::numeric_limits<double>::max());
  return sphere;
}

std::optional<Ecef> horizonOcclusionPoint(const Ecef& direction, std::span<const Ecef> points,
                                          double minimumHeight) noexcept {
  // Cesium tests a tile's point against the ellipsoid shrunk by the tile's minimum height when
  // that is below zero (isScaledSpacePointVisiblePossiblyUnderEllipsoid), so the point must be
  // computed in that ellipsoid's scaled space.
  double shrink = 0.0;
  if (minimumHeight < 0.0 && kSemiMinorAxis > -minimumHeight)
    shrink = minimumHeight;
  const Ecef radii{kSemiMajorAxis + shrink, kSemiMajorAxis + shrink, kSemiMinorAxis + shrink};
  const auto scaled = [&radii](const Ecef& p) {
    return Ecef{p[0] / radii[0], p[1] / radii[1], p[2] / radii[2]};
  };
  Ecef towards = scaled(direction);
  const double towardsNorm = norm(towards);
  if (!(towardsNorm > 0.0))
    return std::nullopt;
  for (double& c : towards)
    c /= towardsNorm;

  double magnitude = 0.0;
  for (const Ecef& p : points) {
    const Ecef s = scaled(p);
    const double length = norm(s);
    const Ecef unit{s[0] / length, s[1] / length, s[2] / length};
    // Points under the ellipsoid count as on it (Cesium's computeMagnitude).
    const double clamped = std::max(1.0, length);
    const double cosAlpha = dot(unit, towards);
    const double sinAlpha = norm(cross(unit, towards));
    const double cosBeta = 1.0 / clamped;
    const double sinBeta = std::sqrt(clamped * clamped - 1.0) * cosBeta;
    const double candidate = 1.0 / (cosAlpha * cosBeta - sinAlpha * sinBeta);
    if (candidate < 0.0)
      return std::nullopt;
    magnitude = std::max(magnitude, candidate);
  }
  if (!(magnitude > 0.0) || !std::isfinite(magnitude))
    return std::nullopt;
  return Ecef{towards[0] * magnitude, towards[1] * magnitude, towards[2] * magnitude};
}

} // namespace strahler::encoding::wgs84
