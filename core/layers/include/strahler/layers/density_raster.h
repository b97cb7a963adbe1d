#pragma once
// The vegetation layer's raster in one pass: one gradient per pixel for the sediment and the
// humidity, and the costly sky view only where the density needs it.

#include "strahler/layers/bordered_heights.h"
#include "strahler/layers/vegetation_density.h"

#include <cstdint>
#include <span>
#include <vector>

namespace strahler::layers {

/// vegetationDensity() of `species` at every pixel of `grid` (an even raster whose pixel (0, 0)
/// has even global indices, border ≥ SkyView::kReach + 1), row-major width · height: exactly
/// vegetationDensity(species, sedimentThickness(grid), skyView(grid, 2), humidity(grid, w),
/// water) with w riverWetness() at step 2 of the grid's samples, but with one gradient per
/// pixel and the sky view computed only at the even pixels some pixel with soil (C_S > 0) and
/// no water interpolates from. `wetnessEven`: riverWetnessEven() of the grid's samples;
/// `water`: the water mask at the pixels (non-zero: water), width · height.
std::vector<double> vegetationDensityRaster(const Species& species, const BorderedHeights& grid,
                                            std::span<const double> wetnessEven,
                                            std::span<const std::uint8_t> water);

} // namespace strahler::layers
