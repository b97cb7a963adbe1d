#pragma once

#include "strahler/analysis/network_analysis.h"
#include "strahler/blocks/block_set.h"
#include "strahler/geometry/polygon.h"
#include "strahler/image/image.h"
#include "strahler/network/river_network.h"

namespace strahler::render {

/// Draws the land, the blocks (tinted by watershed, outlined), the rivers (width by Strahler
/// order, colour by Rosgen type) and the mouths, `longSide` pixels along the longer side.
image::RgbImage drawNetworkImage(const geometry::MultiPolygon& land,
                                 const network::RiverNetwork& network,
                                 const blocks::BlockSet& blocks,
                                 const analysis::NetworkAnalysis& analysis, int longSide);

} // namespace strahler::render
