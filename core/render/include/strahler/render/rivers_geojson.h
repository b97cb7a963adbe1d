#pragma once

#include "strahler/analysis/network_analysis.h"
#include "strahler/geometry/projection.h"
#include "strahler/network/river_network.h"

#include <string>

namespace strahler::render {

/// The river network as GeoJSON (RFC 7946, WGS84): one LineString Feature per river
/// section (a run of edges with the same Strahler order and Rosgen type) with properties
/// strahler, flow (m³/s at its downstream end), rosgen, and elevation at both ends; mouths as
/// Point features with their priority.
std::string riversGeoJson(const network::RiverNetwork& network,
                          const analysis::NetworkAnalysis& analysis,
                          const geometry::LocalProjection& projection);

} // namespace strahler::render
