#pragma once
// Private to core/repair: the Boost.Geometry types the repair works with, and conversions.
// Coordinates are (lon, lat) in degrees, treated as a plane (the rings are small next to the
// Earth; only the report's areas take the latitude into account).

#include "strahler/geometry/polygon.h"

#include <boost/geometry.hpp>
#include <boost/geometry/algorithms/point_on_surface.hpp>
#include <boost/geometry/geometries/point_xy.hpp>

namespace strahler::repair::detail {

namespace bg = boost::geometry;

using Point = bg::model::d2::point_xy<double>;
using BgRing = bg::model::ring<Point, false, true>;       ///< Counter-clockwise, closed.
using BgPolygon = bg::model::polygon<Point, false, true>; ///< Outer CCW, holes CW, closed.
using BgMulti = bg::model::multi_polygon<BgPolygon>;
using BgLine = bg::model::linestring<Point>;
using Box = bg::model::box<Point>;

inline Point toPoint(geometry::Vec2 v) {
  return {v.x, v.y};
}
inline geometry::Vec2 toVec(const Point& p) {
  return {p.x(), p.y()};
}

/// The ring closed (front repeated at the back), in the same order.
inline BgRing toBgRing(const geometry::Ring& ring) {
  BgRing out;
  out.reserve(ring.size() + 1);
  for (const geometry::Vec2 v : ring)
    out.push_back(toPoint(v));
  if (!ring.empty())
    out.push_back(toPoint(ring.front()));
  return out;
}

/// The ring without its closing point.
inline geometry::Ring fromBgRing(const BgRing& ring) {
  geometry::Ring out;
  for (std::size_t i = 0; i + 1 < ring.size(); ++i)
    out.push_back(toVec(ring[i]));
  return out;
}

/// A polygon of one ring, oriented counter-clockwise.
inline BgPolygon polygonOf(const geometry::Ring& ring) {
  BgPolygon polygon;
  polygon.outer() = toBgRing(ring);
  bg::correct(polygon);
  return polygon;
}

/// The polygon with closed rings, its orientation as given.
inline BgPolygon bgPolygonOf(const geometry::Polygon& polygon) {
  BgPolygon out;
  out.outer() = toBgRing(polygon.outer);
  for (const geometry::Ring& hole : polygon.holes)
    out.inners().push_back(toBgRing(hole));
  return out;
}

/// Boost.Geometry's polygons as strahler's (open rings).
inline geometry::MultiPolygon multiPolygonOf(const BgMulti& area) {
  geometry::MultiPolygon land;
  for (const BgPolygon& bgPolygon : area) {
    geometry::Polygon polygon{fromBgRing(bgPolygon.outer()), {}};
    for (const auto& hole : bgPolygon.inners())
      polygon.holes.push_back(fromBgRing(hole));
    land.push_back(std::move(polygon));
  }
  return land;
}

/// The union of two areas.
inline BgMulti unite(const BgMulti& a, const BgMulti& b) {
  BgMulti out;
  bg::union_(a, b, out);
  return out;
}

/// Area in km² of a geometry in degrees: the plane area times the local scale of a sphere of
/// radius 6,371 km at the latitude of the middle of its bounding box.
template <class Geometry> double areaKm2(const Geometry& g) {
  if (bg::is_empty(g))
    return 0.0;
  constexpr double kKmPerDegree = 6371.0 * 3.14159265358979323846 / 180.0;
  const auto box = bg::return_envelope<Box>(g);
  const double lat = 0.5 * (box.min_corner().y() + box.max_corner().y());
  return std::abs(bg::area(g)) * kKmPerDegree * kKmPerDegree *
         std::cos(lat * 3.14159265358979323846 / 180.0);
}

} // namespace strahler::repair::detail
