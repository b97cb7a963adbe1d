#pragma once

#include "strahler/geometry/aabb.h"
#include "strahler/geometry/vec2.h"

#include <vector>

namespace strahler::geometry {

/// A closed ring of vertices; the closing vertex is implicit (front() is not repeated).
using Ring = std::vector<Vec2>;

/// A polygon: one outer ring (counter-clockwise) and holes (clockwise), e.g. an island and
/// its lakes.
struct Polygon {
  Ring outer;
  std::vector<Ring> holes;
};

/// Several disjoint polygons, e.g. an archipelago.
using MultiPolygon = std::vector<Polygon>;

/// Signed area of a ring (positive when counter-clockwise), m² in a metric frame.
double signedArea(const Ring& ring) noexcept;
/// Area of a polygon: outer minus holes, always >= 0.
double area(const Polygon& polygon) noexcept;
/// Total area of a multipolygon.
double area(const MultiPolygon& polygons) noexcept;
/// Bounding box of a ring.
Aabb bounds(const Ring& ring) noexcept;
/// Bounding box of every ring of every polygon.
Aabb bounds(const MultiPolygon& polygons) noexcept;
/// Even-odd point-in-ring test (points on the border may go either way).
bool contains(const Ring& ring, Vec2 p) noexcept;
/// Point inside the outer ring and outside every hole.
bool contains(const Polygon& polygon, Vec2 p) noexcept;
/// Total perimeter of all rings.
double perimeter(const MultiPolygon& polygons) noexcept;
/// Reorients rings in place: outer counter-clockwise, holes clockwise.
void orient(Polygon& polygon) noexcept;
/// Number of vertices of all rings.
std::size_t vertexCount(const MultiPolygon& polygons) noexcept;
/// Area centroid of a multipolygon (outer rings minus holes).
Vec2 centroid(const MultiPolygon& polygons) noexcept;

/// Clips `ring` to the convex, counter-clockwise polygon `window` (Sutherland-Hodgman).
/// The result has the exact area of the intersection; where the window cuts a concave ring
/// into several pieces they stay joined by zero-width bridges along the window's border.
Ring clipToConvex(const Ring& ring, const Ring& window);

} // namespace strahler::geometry
