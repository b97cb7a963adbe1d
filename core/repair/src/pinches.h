#pragma once
// Private to core/repair: land that touches itself at single points, joined there.

#include "strahler/geometry/polygon.h"
#include "strahler/repair/coast_repair.h"

#include <vector>

namespace strahler::repair::detail {

/// Finds the points where the land touches itself (a vertex shared by two rings, or met twice
/// by one: two lobes, or a lake touching the shore), which Boost.Geometry's polygons allow and
/// strahler's do not, and unites a rhombus of land at each, at most 10 m across and a quarter
/// of the shortest segment ending there, reporting each (kPinch, with the land it added).
/// Polygons without such a point stay as they are. A few rounds at most: a rhombus could make
/// a new contact where shores run close; the coastline reader's checks catch what is left.
geometry::MultiPolygon closePinches(geometry::MultiPolygon land, std::vector<Change>& changes);

} // namespace strahler::repair::detail
