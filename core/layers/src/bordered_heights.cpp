#include "strahler/layers/bordered_heights.h"

#include "strahler/base/assert.h"

namespace strahler::layers {

void BorderedHeights::check() const {
  STRAHLER_ASSERT(width > 0 && height > 0 && border >= 1, "BorderedHeights: bad sizes");
  STRAHLER_ASSERT(heights.size() == stride() * static_cast<std::size_t>(height + 2 * border),
                  "BorderedHeights: sample count does not match the sizes");
  STRAHLER_ASSERT(rowSpacing.size() == static_cast<std::size_t>(height + 2 * border),
                  "BorderedHeights: one spacing per bordered row");
}

Gradient gradientAt(const BorderedHeights& grid, int x, int y) noexcept {
  const double spacing = grid.spacing(y);
  return {(grid.at(x + 1, y) - grid.at(x - 1, y)) / (2 * spacing),
          (grid.at(x, y - 1) - grid.at(x, y + 1)) / (2 * spacing)}; // rows run south
}

double concavityAt(const BorderedHeights& grid, int x, int y) noexcept {
  const double mean =
      0.25 * (grid.at(x + 1, y) + grid.at(x - 1, y) + grid.at(x, y - 1) + grid.at(x, y + 1));
  return (mean - grid.at(x, y)) / grid.spacing(y);
}

} // namespace strahler::layers
