#include "strahler/layers/density_raster.h"

#include "upsample.h"

#include "strahler/base/assert.h"
#include "strahler/layers/humidity.h"
#include "strahler/layers/sediment.h"
#include "strahler/layers/sky_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::layers {
namespace {

static_assert(Sediment::kConcavityScale == Humidity::kConcavityScale,
              "one hollow factor for the sediment and the humidity");

/// Per pixel of one row: the sediment S (m) and the local wetness index, from one gradient and one
/// concavity, in the very operations of gradientAt(), concavityAt(), sedimentOf() and
/// localWetness() (the same doubles), over contiguous rows so that the loop vectorises.
void localRow(const BorderedHeights& grid, int y, double* sediment, double* local) {
  static const double tanRepose = std::tan(Sediment::kReposeDeg * std::numbers::pi / 180.0);
  static const double tanDry = std::tan(Humidity::kDrySlopeDeg * std::numbers::pi / 180.0);
  const double spacing = grid.spacing(y);
  const double* row = &grid.heights[static_cast<std::size_t>(y + grid.border) * grid.stride() +
                                    static_cast<std::size_t>(grid.border)];
  const double* north = row - grid.stride();
  const double* south = row + grid.stride();
  const auto width = static_cast<std::ptrdiff_t>(grid.width);
  for (std::ptrdiff_t x = 0; x < width; ++x) {
    const double dzdx = (row[x + 1] - row[x - 1]) / (2 * spacing);
    const double dzdy = (north[x] - south[x]) / (2 * spacing);
    const double tanSlope = std::sqrt(dzdx * dzdx + dzdy * dzdy);
    const double mean = 0.25 * (row[x + 1] + row[x - 1] + north[x] + south[x]);
    const double concavity = (mean - row[x]) / spacing;
    // std::clamp and std::max, spelled as selects of values so that the loop vectorises.
    const double c = 0.5 + concavity / (2.0 * Sediment::kConcavityScale);
    const double hollow = c < 0.0 ? 0.0 : (1.0 < c ? 1.0 : c);
    const double s = 1.0 - tanSlope / tanRepose, f = 1.0 - tanSlope / tanDry;
    const double stable = 0.0 < s ? s : 0.0;
    const double flat = 0.0 < f ? f : 0.0;
    sediment[x] = Sediment::kMaxM * stable * hollow;
    local[x] = Humidity::kLocalWeight * flat * hollow;
  }
}

/// upsampleEven()'s value at pixel (x, y) from the even pixels' `coarse` values, cw per row.
double bilinearAt(const std::vector<double>& coarse, std::size_t cw, std::size_t x,
                  std::size_t y) noexcept {
  const double ty = y % 2 == 1 ? 0.5 : 0.0, tx = x % 2 == 1 ? 0.5 : 0.0;
  const double* a = &coarse[y / 2 * cw + x / 2];
  const double top = a[0] + tx * (a[1] - a[0]);
  const double bottom = a[cw] + tx * (a[cw + 1] - a[cw]);
  return ty == 0.0 ? top : top + ty * (bottom - top);
}

/// ResponseCurve::operator(), here so that the per-pixel loops inline it (the same doubles).
double curveAt(const ResponseCurve& c, double x) noexcept {
  if (x < c.rise0 || x > c.fall0)
    return 0.0;
  if (x < c.rise1)
    return c.rise1 > c.rise0 ? (x - c.rise0) / (c.rise1 - c.rise0) : 1.0;
  if (x > c.fall1)
    return c.fall0 > c.fall1 ? (c.fall0 - x) / (c.fall0 - c.fall1) : 1.0;
  return 1.0;
}

} // namespace

std::vector<double> vegetationDensityRaster(const Species& species, const BorderedHeights& grid,
                                            std::span<const double> wetnessEven,
                                            std::span<const std::uint8_t> water) {
  grid.check();
  const auto width = static_cast<std::size_t>(grid.width),
             height = static_cast<std::size_t>(grid.height);
  const std::size_t cw = width / 2 + 1, ch = height / 2 + 1;
  STRAHLER_ASSERT(width % 2 == 0 && height % 2 == 0, "vegetationDensityRaster: an even raster");
  STRAHLER_ASSERT(wetnessEven.size() == cw * ch && water.size() == width * height,
                  "vegetationDensityRaster: one wetness per even pixel, one water flag per pixel");
  // Where there is water or no soil (C_S = 0) the density is 0 whatever the sky: the even
  // pixels only such pixels read (their own and, at odd indices, the next ones) need no sky.
  // soil: C_S, 0 on water (vegetationDensity() is 0 there).
  std::vector<double> soil(width * height), local(width * height);
  std::vector<std::uint8_t> wanted(cw * ch, 0);
  for (std::size_t y = 0; y < height; ++y) {
    localRow(grid, static_cast<int>(y), &soil[y * width], &local[y * width]);
    for (std::size_t x = 0; x < width; ++x) {
      const std::size_t k = y * width + x;
      soil[k] = water[k] != 0 ? 0.0 : curveAt(species.sediment, soil[k]);
      if (soil[k] == 0.0)
        continue;
      for (std::size_t j = y / 2; j <= (y + 1) / 2; ++j)
        for (std::size_t i = x / 2; i <= (x + 1) / 2; ++i)
          wanted[j * cw + i] = 1;
    }
  }
  const std::vector<double> sky = skyViewEven(grid, wanted);
  const std::vector<double> wet(wetnessEven.begin(), wetnessEven.end());
  std::vector<double> density(width * height, 0.0);
  for (std::size_t y = 0; y < height; ++y)
    for (std::size_t x = 0; x < width; ++x) {
      const std::size_t k = y * width + x;
      if (soil[k] == 0.0) // vegetationDensity(): C_S · (C_I + C_H) = 0 · (…)
        continue;
      const double humidity = grid.at(static_cast<int>(x), static_cast<int>(y)) < 0.0
                                  ? 1.0
                                  : std::max(bilinearAt(wet, cw, x, y), local[k]);
      // vegetationDensity()'s operations on the same doubles.
      const double d = soil[k] * (curveAt(species.illumination, bilinearAt(sky, cw, x, y)) +
                                  curveAt(species.humidity, humidity));
      density[k] = std::clamp(0.5 * d, 0.0, 1.0);
    }
  return density;
}

} // namespace strahler::layers
