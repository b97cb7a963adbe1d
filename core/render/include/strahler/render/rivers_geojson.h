#pragma once

#include "strahler/construction/world_data.h"
#include "strahler/geometry/projection.h"

#include <string>

namespace strahler::render {

/// Douglas–Peucker tolerance of the river lines, in metres.
inline constexpr double kRiverLineTolerance = 2.0;

/// The river network of `world` as GeoJSON (RFC 7946, WGS84): one LineString Feature per river
/// section (a run of edges with the same Strahler order and Rosgen type) that follows the
/// curves of its river primitives (the carved channels, meanders included), simplified to
/// within kRiverLineTolerance, with properties strahler, rosgen, flow (m³/s at its downstream
/// end), widthUpM and widthDownM (channel width at both ends, m), elevationUp, elevationDown
/// and tree; mouths as Point features with their priority. A section without primitives (a
/// world whose rivers do not match its network) falls back to its straight edges.
std::string riversGeoJson(const construction::WorldData& world,
                          const geometry::LocalProjection& projection);

} // namespace strahler::render
