#pragma once

#include "strahler/base/result.h"
#include "strahler/geometry/polygon.h"
#include "strahler/input/limits.h"

#include <string_view>

namespace strahler::input {

/// Parses a coastline from GeoJSON (RFC 7946): a Polygon, MultiPolygon, Feature or
/// FeatureCollection of those. Coordinates stay (lon, lat) in degrees; holes are lakes.
/// Errors name the place (feature, polygon, ring, position index) and the fault: not JSON,
/// too deep, empty or non-polygon geometry, unclosed ring, fewer than 4 positions, NaN or
/// infinite or out-of-range lon/lat, self-intersecting ring, hole outside its polygon,
/// overlapping polygons, more vertices or rings than `limits`. Rings come back without the
/// repeated closing position and without consecutive duplicates, in the input's orientation.
/// Coastlines spanning more than 180° of longitude (those crossing the antimeridian) are
/// refused with kUnsupported. Codes: kInvalidInput for malformed input, kOutOfRange for
/// lon/lat outside [-180, 180] x [-90, 90], kLimitExceeded for anything above `limits`.
base::Result<geometry::MultiPolygon> parseCoastline(std::string_view geojson,
                                                    const InputLimits& limits = {});

/// The embedded default coastline: a fictitious island of about 1,000 km² with a lake,
/// as GeoJSON text.
std::string_view defaultCoastlineGeoJson() noexcept;

} // namespace strahler::input
