#pragma once

#include "strahler/blocks/block_set.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/input/world_spec.h"
#include "strahler/network/river_network.h"

#include <vector>

namespace strahler::analysis {

/// Per node: the area (km²) of its block plus every block upstream of it.
std::vector<double> drainageAreasKm2(const network::RiverNetwork& network,
                                     const blocks::BlockSet& blocks);

/// Gives the rivers concave long profiles (stream-power steady state): every node is set
/// above its parent by L · s(p) · (A / referenceArea)^−concavity (at least 1 cm), where L is
/// the edge's length, p its midpoint, s(p) the elevation law's river slope (ReliefLaw) and A
/// the node's drainage area; mouths keep their elevation. Steep headwaters, gentle lowlands,
/// monotone downstream and consistent at confluences. `blocks` must come from `network`.
void shapeRiverProfiles(const input::WorldSpec& spec, const geometry::PolygonIndex& land,
                        const blocks::BlockSet& blocks, network::RiverNetwork& network);

} // namespace strahler::analysis
