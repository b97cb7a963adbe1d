#pragma once
// Private to core/repair: land that touches itself at single points, joined there.

#include "strahler/geometry/polygon.h"
#include "strahler/repair/coast_repair.h"

#include <vector>

namespace strahler::repair::detail {

/// Finds the points where the land touches itself (two boundary segments meeting anywhere but
/// at the shared vertex of consecutive ones: two lobes, or a lake touching the shore), which
/// Boost.Geometry's polygons allow and strahler's do not, and unites a rhombus of land at
/// each, at most 10 m across and a quarter of the distance to the nearest other vertex there,
/// reporting each (kPinch, with the land it added). Polygons without such a point stay as
/// they are; polygons the union returns inside other land are left out. A few rounds at most:
/// a rhombus could make a new contact where shores run close; the coastline reader's checks
/// catch what is left.
geometry::MultiPolygon closePinches(geometry::MultiPolygon land, std::vector<Change>& changes);

} // namespace strahler::repair::detail
