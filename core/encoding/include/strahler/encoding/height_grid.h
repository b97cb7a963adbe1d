#pragma once

#include <vector>

namespace strahler::encoding {

/// Heights of a raster tile in image order: row 0 is the northern (top) row, column 0 the
/// western one. Invariant: heights.size() == width * height.
struct HeightGrid {
  int width = 0;
  int height = 0;
  std::vector<float> heights; ///< Metres above sea level (negative below).
};

} // namespace strahler::encoding
