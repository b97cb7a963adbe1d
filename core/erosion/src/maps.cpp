#include "grid_ops.h"

#include "strahler/erosion/erosion.h"
#include "strahler/layers/bordered_heights.h"
#include "strahler/layers/sky_view.h"

#include <cmath>
#include <cstdint>
#include <numeric>

namespace strahler::erosion {

std::vector<double> illuminationMap(std::span<const double> heights, int width, int height,
                                    double spacing, int threads) {
  const int border = layers::SkyView::kReach;
  std::vector<double> bordered;
  detail::extendEdges(heights, width, height, border, bordered);
  const std::vector<double> spacings(static_cast<std::size_t>(height + 2 * border), spacing);
  std::vector<double> out(heights.size());
  const std::size_t stride = static_cast<std::size_t>(width + 2 * border);
  // A band of rows is a contiguous run of the bordered samples, so each band is its own
  // BorderedHeights and skyView gives it the whole grid's values exactly.
  detail::forBands(height, threads, [&](int y0, int y1) {
    if (y0 == y1)
      return;
    layers::BorderedHeights band;
    band.width = width;
    band.height = y1 - y0;
    band.border = border;
    band.heights = std::span<const double>(bordered).subspan(
        static_cast<std::size_t>(y0) * stride,
        static_cast<std::size_t>(y1 - y0 + 2 * border) * stride);
    band.rowSpacing = std::span<const double>(spacings).subspan(
        static_cast<std::size_t>(y0), static_cast<std::size_t>(y1 - y0 + 2 * border));
    const std::vector<double> values = layers::skyView(band, 1);
    std::copy(values.begin(), values.end(),
              out.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y0) *
                                                        static_cast<std::size_t>(width)));
  });
  return out;
}

std::vector<double> humidityMap(std::span<const double> heights, int width, int height,
                                double spacing) {
  const std::size_t n = heights.size();
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  // Highest first; equal heights by index, so the order is total and the result unique.
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return heights[a] != heights[b] ? heights[a] > heights[b] : a < b;
  });
  std::vector<double> water(n, 1.0);
  for (const std::uint32_t i : order) {
    const int x = static_cast<int>(i % static_cast<std::uint32_t>(width));
    const int y = static_cast<int>(i / static_cast<std::uint32_t>(width));
    double weights[8] = {};
    double total = 0.0;
    for (int k = 0; k < 8; ++k) {
      const int nx = x + detail::kDx[k];
      const int ny = y + detail::kDy[k];
      if (nx < 0 || ny < 0 || nx >= width || ny >= height)
        continue;
      const double drop =
          heights[i] - heights[static_cast<std::size_t>(ny) * static_cast<std::size_t>(width) +
                               static_cast<std::size_t>(nx)];
      if (drop <= 0.0)
        continue;
      weights[k] = drop / (k < 4 ? spacing : spacing * std::sqrt(2.0));
      total += weights[k];
    }
    if (total <= 0.0)
      continue;
    for (int k = 0; k < 8; ++k)
      if (weights[k] > 0.0)
        water[static_cast<std::size_t>(y + detail::kDy[k]) * static_cast<std::size_t>(width) +
              static_cast<std::size_t>(x + detail::kDx[k])] += water[i] * weights[k] / total;
  }
  const double most = *std::max_element(water.begin(), water.end());
  std::vector<double> out(n, 1.0);
  if (most > 1.0)
    for (std::size_t i = 0; i < n; ++i)
      out[i] = std::log(water[i]) / std::log(most);
  return out;
}

} // namespace strahler::erosion
