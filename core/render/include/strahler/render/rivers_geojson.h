#pragma once

#include "strahler/geometry/projection.h"
#include "strahler/network/river_network.h"
#include "strahler/primitives/river_primitive.h"

#include <string>
#include <vector>

namespace strahler::render {

/// The river network as GeoJSON (RFC 7946, WGS84): one LineString Feature per river
/// section (a run of edges with the same Strahler order and Rosgen type) with properties
/// strahler, flow (m³/s at its downstream end), rosgen, and elevation at both ends; mouths as
/// Point features with their priority.
/// `flow` and `types` hold one value per node.
std::string riversGeoJson(const network::RiverNetwork& network, const std::vector<double>& flow,
                          const std::vector<primitives::RiverType>& types,
                          const geometry::LocalProjection& projection);

} // namespace strahler::render
