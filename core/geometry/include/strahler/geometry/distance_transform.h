#pragma once

#include <cstdint>
#include <vector>

namespace strahler::geometry {

/// Euclidean distance in metres from each cell centre of a width × height grid of square
/// cells `cellSize` metres wide to the nearest marked cell centre (Felzenszwalb–Huttenlocher
/// exact transform, O(n)); +inf everywhere when none is marked. `marked` has width * height
/// entries, row after row, non-zero for marked cells.
std::vector<float> distanceToMarked(int width, int height, double cellSize,
                                    const std::vector<std::uint8_t>& marked);

} // namespace strahler::geometry
