#pragma once
// Private to core/input: topology checks of a parsed coastline, in (lon, lat) degrees.

#include "strahler/base/result.h"
#include "strahler/geometry/polygon.h"

#include <cstdint>
#include <string>
#include <vector>

namespace strahler::input::detail {

/// A ring as parsed: vertices without the closing repeat or consecutive duplicates, and the
/// GeoJSON position index each vertex came from (for error messages).
struct ParsedRing {
  geometry::Ring vertices;
  std::vector<std::uint32_t> positions; ///< positions[i]: JSON index of vertices[i].
  std::uint32_t closingPosition = 0;    ///< JSON index of the repeated first position.
};

/// A polygon as parsed: rings[0] is the outer ring, the others are holes.
struct ParsedPolygon {
  std::string label; ///< "feature 2, polygon 0" or "polygon 1": where it is in the input.
  std::vector<ParsedRing> rings;
};

/// Checks one ring on its own: at least 3 distinct vertices, no spike (a segment doubling
/// back along the previous one). `where` prefixes errors.
base::Status checkRingShape(const ParsedRing& ring, const std::string& where);

/// Checks the whole coastline: no two segments touch or cross (except consecutive segments
/// of one ring at their shared vertex; the error gives the place in degrees), no ring has
/// zero area, every hole lies inside its outer ring and outside the other holes, and no
/// polygon lies inside another (islands in lakes are allowed).
/// Runs in about O(n log n) for n segments: a sparse grid with cells of about the mean
/// segment length; inputs dense enough to need more than `maxPairTests` segment-pair tests
/// are refused with kLimitExceeded rather than taking quadratic time.
base::Status checkTopology(const std::vector<ParsedPolygon>& polygons, std::uint64_t maxPairTests);

} // namespace strahler::input::detail
