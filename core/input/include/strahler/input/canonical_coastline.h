#pragma once

#include "strahler/geometry/polygon.h"

#include <string>
#include <vector>

namespace strahler::input {

/// Puts a validated coastline (lon, lat in degrees) in its one canonical form, so that the same
/// land gives the same world and cache key however its GeoJSON was written: outer rings
/// counter-clockwise and holes clockwise (RFC 7946's right-hand rule; the local frame keeps
/// the orientation), each ring starting at its lexicographically smallest (lon, lat) vertex,
/// each polygon's holes and then the polygons in the order of those first vertices. The
/// orientation is read at that smallest vertex, a corner of the convex hull, from its two
/// neighbours, an exact test that a reversed ring answers with the opposite sign.
void canonicalizeCoastline(geometry::MultiPolygon& lonLat);

/// Warnings for a coastline whose coordinates look like [latitude, longitude] instead of
/// GeoJSON's [longitude, latitude]: the centre of the land's bounding box within 1 degree of
/// the equator and every longitude within ±90 (a place near the prime meridian, swapped). Empty
/// when nothing looks swapped. Latitudes beyond ±90 are refused by the reader, whose error says the
/// same.
std::vector<std::string> swappedCoordinateWarnings(const geometry::MultiPolygon& lonLat);

} // namespace strahler::input
