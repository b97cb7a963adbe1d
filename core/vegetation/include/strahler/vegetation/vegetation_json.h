#pragma once

#include "strahler/geometry/projection.h"
#include "strahler/vegetation/placement.h"
#include "strahler/vegetation/web_tile.h"

#include <span>
#include <string>

namespace strahler::vegetation {

/// The JSON body of GET /worlds/{id}/vegetation/{z}/{x}/{y}.json (docs/architecture.md,
/// "Vegetation"): the species table, then one object per instance with its tile coordinates,
/// lon/lat, species, radius, rotation, scale and id. Numbers are written with fixed digits
/// (locale-independent), so the same instances always give the same bytes. With `heights`
/// (one per instance, m), each instance also carries "e", "n" (its position in the world's
/// local metres, east and north, as the local pyramid's tiles) and "h" (the ground height).
std::string writeVegetationJson(const geometry::TileId& tile,
                                const geometry::LocalProjection& projection,
                                std::span<const Instance> instances,
                                std::span<const double> heights = {});

} // namespace strahler::vegetation
