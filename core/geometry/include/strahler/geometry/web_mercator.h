#pragma once

#include "strahler/geometry/vec2.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::geometry {

/// Web Mercator's latitude limit, degrees: where the square map (EPSG:3857) ends, north and
/// south.
inline constexpr double kMaxWebMercatorLatitude = 85.0511287798066;

/// The Mercator northing of a latitude in degrees, in radians of the sphere: asinh(tan φ),
/// north positive (unclamped).
inline double mercatorNorthing(double latitude) noexcept {
  return std::asinh(std::tan(latitude / (180.0 / std::numbers::pi)));
}

/// The latitude in degrees of a Mercator northing in radians: atan(sinh y), the inverse of
/// mercatorNorthing().
inline double latitudeOfNorthing(double northing) noexcept {
  return std::atan(std::sinh(northing)) * (180.0 / std::numbers::pi);
}

/// Web Mercator (EPSG:3857) as the unit square: (lon, lat) in degrees → (0, 0) at the map's
/// north-west corner, (1, 1) at its south-east, x east, y south; the latitude clamped to
/// ±kMaxWebMercatorLatitude. An XYZ tile's coordinates at zoom z are these times 2^z.
inline Vec2 webMercatorUnit(Vec2 lonLat) noexcept {
  const double latitude = std::clamp(lonLat.y, -kMaxWebMercatorLatitude, kMaxWebMercatorLatitude);
  return {(lonLat.x + 180.0) / 360.0, (1.0 - mercatorNorthing(latitude) / std::numbers::pi) / 2.0};
}

/// The inverse of webMercatorUnit() on the map: a point of the unit square → (lon, lat) in
/// degrees.
inline Vec2 lonLatOfWebMercatorUnit(Vec2 unit) noexcept {
  return {unit.x * 360.0 - 180.0, latitudeOfNorthing(std::numbers::pi * (1.0 - 2.0 * unit.y))};
}

} // namespace strahler::geometry
