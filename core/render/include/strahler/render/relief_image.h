#pragma once

#include "strahler/construction/world.h"
#include "strahler/image/image.h"

namespace strahler::render {

/// A shaded-relief overview of a whole world, `longSide` pixels along its longer side:
/// hypsometric tint (greens to browns to grey) lit from the north-west, the sea shaded by
/// depth, and the river curves drawn by Strahler order. Rows are evaluated on `threads`
/// threads; the image is the same for any count.
image::RgbImage drawReliefImage(const construction::World& world, int longSide, int threads = 2);

} // namespace strahler::render
