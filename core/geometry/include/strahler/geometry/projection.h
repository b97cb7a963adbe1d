#pragma once

#include "strahler/geometry/vec2.h"

#include <vector>

namespace strahler::geometry {

/// Mean Earth radius (m) of the spherical model used by every projection here.
inline constexpr double kEarthRadius = 6371008.8;

/// Lambert azimuthal equal-area projection on the sphere, centred on a world's centroid.
/// Local frame: metres, x east, y north, origin at the centre. Equal-area, so km² measured
/// in the local frame are true km²; distances are within 0.1 % over 100 km of the centre.
class LocalProjection {
public:
  /// Projection centred on (lon0, lat0) in degrees.
  LocalProjection(double lon0 = 0.0, double lat0 = 0.0) noexcept;

  /// (lon, lat) in degrees to local metres.
  Vec2 forward(Vec2 lonLat) const noexcept;
  /// Local metres to (lon, lat) in degrees.
  Vec2 inverse(Vec2 xy) const noexcept;
  /// forward() of every (lons[i], lats[j]), row-major (out[j · lons.size() + i]), with the
  /// trigonometry done once per row and once per column instead of once per point.
  void forwardGrid(const std::vector<double>& lons, const std::vector<double>& lats,
                   std::vector<Vec2>& out) const;
  /// The centre (lon0, lat0) in degrees.
  Vec2 center() const noexcept { return {lon0_, lat0_}; }

private:
  double lon0_;
  double lat0_;
  double sinLat0_;
  double cosLat0_;
};

} // namespace strahler::geometry
