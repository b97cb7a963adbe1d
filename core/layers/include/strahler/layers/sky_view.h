#pragma once

#include "strahler/layers/bordered_heights.h"

#include <cstdint>
#include <span>
#include <vector>

namespace strahler::layers {

/// The seed's illumination I: the share of the sky a point sees, from N rays of length L.
struct SkyView {
  /// N: rays per pixel, at azimuths 2πi/N (i < N), the first due north.
  static constexpr int kRays = 16;
  /// L in pixels: a ray looks this many samples away (L = kReach × the pixel's spacing, so the
  /// layer reads alike at every zoom); with step − 1 more, the border the grid needs.
  static constexpr int kReach = 8;
  /// The samples a ray visits, in pixels from its origin: every step to 4, then every other
  /// (1, 2, 3, 4, 6, 8): six height lookups per ray.
  static constexpr int kSteps[] = {1, 2, 3, 4, 6, 8};
};

/// The sky-view factor of every pixel, row-major width · height, in [0, 1]: for each of the
/// SkyView::kRays rays, the horizon's elevation angle φ (the steepest rise seen along the ray
/// at SkyView::kSteps, 0 when nothing rises), then 1 − mean(sin φ) (Zakšek et al. 2011; the
/// seed's n̂ · d over the rays tangent to the terrain). 1 on open flat ground, lower in valleys
/// and under cliffs. `step` 1 computes every pixel; step 2 (an even raster whose pixel (0, 0)
/// has even global indices, as every tile of an even size) computes every other pixel of every
/// other row and interpolates bilinearly between them, a quarter of the rays for the 1.5×
/// cost budget (docs/performance.md). Asserts grid.border ≥ SkyView::kReach + step − 1.
std::vector<double> skyView(const BorderedHeights& grid, int step = 1);

/// skyView() at step 2 without the interpolation: the values at the even pixels (2i, 2j), i ≤
/// width / 2, j ≤ height / 2 (the last ones in the border), (width / 2 + 1) per row. With
/// `wanted` (one flag per value), only the flagged values are computed, the others are 1.
/// Asserts an even raster and grid.border ≥ SkyView::kReach + 1.
std::vector<double> skyViewEven(const BorderedHeights& grid,
                                std::span<const std::uint8_t> wanted = {});

} // namespace strahler::layers
