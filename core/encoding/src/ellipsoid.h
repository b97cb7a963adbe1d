#pragma once

#include <array>
#include <optional>
#include <span>

namespace strahler::encoding::wgs84 {

/// A point or vector in Earth-centred, Earth-fixed coordinates (x to 0°E, z to the north
/// pole), metres.
using Ecef = std::array<double, 3>;

inline constexpr double kSemiMajorAxis = 6378137.0;                               ///< a, m.
inline constexpr double kFlattening = 1.0 / 298.257223563;                        ///< f.
inline constexpr double kSemiMinorAxis = kSemiMajorAxis * (1.0 - kFlattening);    ///< b, m.
inline constexpr double kEccentricitySquared = kFlattening * (2.0 - kFlattening); ///< e².

/// An angle's sine and cosine, computed once for a grid row or column.
struct SinCos {
  double sin = 0.0;
  double cos = 1.0;
  /// Of an angle in radians.
  static SinCos of(double radians) noexcept;
};

/// The ECEF position of a longitude/latitude at `height` m above the ellipsoid.
Ecef toEcef(SinCos longitude, SinCos latitude, double height) noexcept;
/// The same, angles in radians.
Ecef toEcef(double longitude, double latitude, double height) noexcept;

/// The unit outward normal of the ellipsoid (geodetic up) at a longitude/latitude.
Ecef geodeticUp(SinCos longitude, SinCos latitude) noexcept;

/// Radius of curvature in the prime vertical, N(φ), m (east-west: a parallel's radius is N·cosφ).
double primeVerticalRadius(SinCos latitude) noexcept;

/// Meridional radius of curvature, M(φ), m (north-south).
double meridionalRadius(SinCos latitude) noexcept;

/// A sphere enclosing every point: the centre of their axis-aligned box, radius to the
/// farthest point.
struct Sphere {
  Ecef centre{};
  double radius = 0.0;
};
Sphere enclosingSphere(std::span<const Ecef> points) noexcept;

/// Cesium's horizon occlusion point of `points`, in the scaled space of the ellipsoid shrunk by
/// `minimumHeight` when that is negative (EllipsoidalOccluder::
/// computeHorizonCullingPointFromVerticesPossiblyUnderEllipsoid): along `direction`, as far as
/// the farthest point's horizon needs; points under the ellipsoid count as on it. Empty when
/// Cesium's computation has no answer (some point faces away from `direction`).
std::optional<Ecef> horizonOcclusionPoint(const Ecef& direction, std::span<const Ecef> points,
                                          double minimumHeight) noexcept;

} // namespace strahler::encoding::wgs84
