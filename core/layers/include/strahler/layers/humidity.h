#pragma once

#include "strahler/construction/world.h"
#include "strahler/layers/bordered_heights.h"
#include "strahler/tiling/tile_scheme.h"

#include <span>
#include <vector>

namespace strahler::layers {

/// The seed's humidity H in [0, 1], as a local function of position. The seed accumulates
/// flow downhill over the whole map, which no tile can do alone; the world already did it:
/// its rivers carry the accumulated flow (their width grows with it). So H is the larger of
///  - the rivers' wetness: (exp(−d / R) − e⁻³) / (1 − e⁻³) at distance d from a channel's edge
///    (1 in it, 0 from 3R on), reach R = min(kMaxReachM, kReachBaseM + kReachPerWidth ·
///    channel width):
///    large rivers wet a wide floodplain, brooks a strip;
///  - a local wetness index standing for ln(A / tan β) where A is not local: flat ground and
///    hollows keep water, kLocalWeight · (1 − tan β / tan kDrySlopeDeg)₊ · C, C the concavity
///    factor of Sediment (0.5 on a plane).
/// Water (h < 0: sea and land below it) is 1.
struct Humidity {
  static constexpr double kReachBaseM = 30.0;     ///< R of the narrowest river, m.
  static constexpr double kReachPerWidth = 4.0;   ///< R grows by this many channel widths.
  static constexpr double kMaxReachM = 200.0;     ///< R of the widest rivers, m.
  static constexpr double kLocalWeight = 0.6;     ///< The local index's largest value.
  static constexpr double kDrySlopeDeg = 30.0;    ///< Slope at which the local index is 0.
  static constexpr double kConcavityScale = 0.05; ///< As Sediment::kConcavityScale.
};

/// The rivers' wetness (Humidity) at the points of `grid` (a raster grid, rows west to east)
/// inside a border of `border` samples, row-major (grid.width − 2·border) · (grid.height −
/// 2·border); at each sample, rivers whose whole reach (3R) is under half its row's spacing are
/// left out (so a sample's value is its own, whatever the grid). `step` 2 (an even raster
/// inside the border whose first pixel has even global indices, as every tile of an even size)
/// computes every other sample of every other row and interpolates bilinearly, as skyView().
std::vector<double> riverWetness(const construction::World& world, const tiling::SampleGrid& grid,
                                 int border, int step = 1);

/// riverWetness() at step 2 without the interpolation: the values at every other sample of
/// every other row inside the border, the last row and column the border's first, (inside / 2
/// + 1) per row, inside / 2 + 1 rows (the even pixels of vegetationDensityRaster()).
std::vector<double> riverWetnessEven(const construction::World& world,
                                     const tiling::SampleGrid& grid, int border);

/// The samples of the bordered raster `grid` inside its border of `border` samples, as a raster
/// grid of their own: step 1 every one (inside width × height); step 2 every other sample of
/// every other row from the first inside, the last ones the border's first ((inside / 2 + 1)²
/// for a square; asserts border ≥ 1 and an even inside).
tiling::SampleGrid samplesInside(const tiling::SampleGrid& grid, int border, int step);

/// The local wetness index of Humidity at a point of slope `tanSlope` (tan β) and concavity
/// `concavity` (concavityAt()), 0 … Humidity::kLocalWeight.
double localWetness(double tanSlope, double concavity) noexcept;

/// H of every pixel, row-major width · height; `wetness` is riverWetness() of the bordered
/// grid of `grid`'s samples (one value per pixel).
std::vector<double> humidity(const BorderedHeights& grid, std::span<const double> wetness);

} // namespace strahler::layers
