#pragma once

#include "strahler/base/result.h"
#include "strahler/geometry/polygon.h"
#include "strahler/input/limits.h"
#include "strahler/repair/coast_repair.h"

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
/// Errors for defects that `parseAndRepairCoastline` mends (self-intersections, spikes, rings
/// without area, holes outside their ring, overlapping polygons) end with "; run with
/// --repair to mend it".
base::Result<geometry::MultiPolygon> parseCoastline(std::string_view geojson,
                                                    const InputLimits& limits = {});

/// Parses a coastline like `parseCoastline`, but mends the topology defects instead of
/// refusing them (repair::repairCoastline: duplicate positions, spikes, self-intersections,
/// rings without area, holes outside their ring, overlapping polygons, pieces touching at a
/// point; rings reoriented as RFC 7946 asks) and lists each change. Faults of the GeoJSON
/// itself (structure, unclosed rings, fewer than 4 positions, bad numbers, limits) are still
/// refused as `parseCoastline` refuses them. The result passes every check `parseCoastline`
/// makes; if it did not (a bug), the error says that the repair left a defect.
base::Result<repair::RepairedCoast> parseAndRepairCoastline(std::string_view geojson,
                                                            const InputLimits& limits = {});

/// The embedded default coastline: a fictitious island of about 1,000 km² with a lake,
/// as GeoJSON text.
std::string_view defaultCoastlineGeoJson() noexcept;

} // namespace strahler::input
