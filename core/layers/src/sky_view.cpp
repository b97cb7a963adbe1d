#include "strahler/layers/sky_view.h"

#include "upsample.h"

#include "strahler/base/assert.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace strahler::layers {
namespace {

constexpr std::size_t kStepCount = std::size(SkyView::kSteps);

/// One ray: the offsets (in samples) of its steps and their distances in spacings.
struct Ray {
  std::array<int, kStepCount> dx{}, dy{};
  std::array<double, kStepCount> distance{};
};

std::array<Ray, SkyView::kRays> makeRays() {
  std::array<Ray, SkyView::kRays> rays{};
  for (int i = 0; i < SkyView::kRays; ++i) {
    const double theta = 2.0 * std::numbers::pi * i / SkyView::kRays;
    const double east = std::sin(theta), north = std::cos(theta);
    Ray& ray = rays[static_cast<std::size_t>(i)];
    for (std::size_t k = 0; k < kStepCount; ++k) {
      const double s = SkyView::kSteps[k];
      ray.dx[k] = static_cast<int>(std::lround(s * east));
      ray.dy[k] = static_cast<int>(std::lround(-s * north)); // rows run south
      ray.distance[k] = std::hypot(ray.dx[k], ray.dy[k]);
    }
  }
  return rays;
}

const std::array<Ray, SkyView::kRays>& rays() {
  static const std::array<Ray, SkyView::kRays> all = makeRays();
  return all;
}

/// The sky-view factor at `count` consecutive points whose heights are here[0 … count − 1]:
/// `thereOf(ray, k)` gives the heights `count` points long that ray's k-th step reaches from
/// them; `spacing` the row's sample spacing, m. Contiguous runs, so that the loops vectorise.
template <class ThereOf>
void skyRun(const double* here, const ThereOf& thereOf, double spacing, std::size_t count,
            double* out) {
  thread_local std::vector<double> steepest, sum;
  steepest.assign(count, 0.0);
  sum.assign(count, 0.0);
  for (const Ray& ray : rays()) {
    std::fill(steepest.begin(), steepest.end(), 0.0); // tan of the horizon; 0: clear
    for (std::size_t k = 0; k < kStepCount; ++k) {
      const double inverse = 1.0 / (ray.distance[k] * spacing);
      const double* there = thereOf(ray, k);
      for (std::size_t i = 0; i < count; ++i) { // std::max as a select of values: vectorises
        const double rise = (there[i] - here[i]) * inverse;
        steepest[i] = steepest[i] < rise ? rise : steepest[i];
      }
    }
    for (std::size_t i = 0; i < count; ++i) // sin(atan(t))
      sum[i] += steepest[i] / std::sqrt(1.0 + steepest[i] * steepest[i]);
  }
  for (std::size_t i = 0; i < count; ++i)
    out[i] = 1.0 - sum[i] / SkyView::kRays;
}

/// The bordered samples split by column parity (plane 0: even columns, 1: odd), so that every
/// other pixel's ray steps read contiguous memory.
struct ColumnPlanes {
  std::size_t stride = 0; ///< Samples per plane row.
  std::array<std::vector<double>, 2> plane;

  explicit ColumnPlanes(const BorderedHeights& grid) : stride((grid.stride() + 1) / 2) {
    const std::size_t rows = static_cast<std::size_t>(grid.height + 2 * grid.border);
    for (auto& p : plane)
      p.assign(rows * stride, 0.0);
    for (std::size_t r = 0; r < rows; ++r)
      for (std::size_t c = 0; c < grid.stride(); ++c)
        plane[c % 2][r * stride + c / 2] = grid.heights[r * grid.stride() + c];
  }
  /// The samples from bordered row `row`, column `column` on, every other one.
  const double* at(std::size_t row, std::size_t column) const noexcept {
    return &plane[column % 2][row * stride + column / 2];
  }
};

/// The sky-view factor at every pixel of row y, step 1.
void skyRow(const BorderedHeights& grid, int y, double* out) {
  const auto stride = static_cast<std::ptrdiff_t>(grid.stride());
  const double* here = &grid.heights[static_cast<std::size_t>(y + grid.border) * grid.stride() +
                                     static_cast<std::size_t>(grid.border)];
  skyRun(
      here, [&](const Ray& ray, std::size_t k) { return here + ray.dy[k] * stride + ray.dx[k]; },
      grid.spacing(y), static_cast<std::size_t>(grid.width), out);
}

/// The sky-view factor at pixels (x0 + 2i, y), i < count (x0, y even).
void skyRunEven(const BorderedHeights& grid, const ColumnPlanes& planes, int y, int x0,
                std::size_t count, double* out) {
  const int row = y + grid.border, column = x0 + grid.border;
  skyRun(
      planes.at(static_cast<std::size_t>(row), static_cast<std::size_t>(column)),
      [&](const Ray& ray, std::size_t k) {
        return planes.at(static_cast<std::size_t>(row + ray.dy[k]),
                         static_cast<std::size_t>(column + ray.dx[k]));
      },
      grid.spacing(y), count, out);
}

} // namespace

std::vector<double> skyView(const BorderedHeights& grid, int step) {
  grid.check();
  STRAHLER_ASSERT(step == 1 || (step == 2 && grid.width % 2 == 0 && grid.height % 2 == 0),
                  "skyView: step 1, or 2 on an even raster");
  STRAHLER_ASSERT(grid.border >= SkyView::kReach + step - 1,
                  "skyView: the border is shorter than a ray");
  const auto width = static_cast<std::size_t>(grid.width);
  std::vector<double> out(width * static_cast<std::size_t>(grid.height));
  if (step == 1) {
    for (int y = 0; y < grid.height; ++y)
      skyRow(grid, y, &out[static_cast<std::size_t>(y) * width]);
    return out;
  }
  // Every other pixel of every other row, the last in the border (the next tile's first),
  // then bilinear between them: the same global samples whichever tile asks.
  return detail::upsampleEven(skyViewEven(grid), width, static_cast<std::size_t>(grid.height));
}

std::vector<double> skyViewEven(const BorderedHeights& grid, std::span<const std::uint8_t> wanted) {
  grid.check();
  STRAHLER_ASSERT(grid.width % 2 == 0 && grid.height % 2 == 0, "skyViewEven: an even raster");
  STRAHLER_ASSERT(grid.border >= SkyView::kReach + 1,
                  "skyViewEven: the border is shorter than a ray");
  const std::size_t cw = static_cast<std::size_t>(grid.width) / 2 + 1,
                    ch = static_cast<std::size_t>(grid.height) / 2 + 1;
  STRAHLER_ASSERT(wanted.empty() || wanted.size() == cw * ch, "skyViewEven: one flag per value");
  std::vector<double> coarse(cw * ch, 1.0);
  const ColumnPlanes planes(grid);
  for (std::size_t j = 0; j < ch; ++j) {
    if (wanted.empty()) {
      skyRunEven(grid, planes, static_cast<int>(2 * j), 0, cw, &coarse[j * cw]);
      continue;
    }
    for (std::size_t i = 0; i < cw;) { // the runs of wanted values along the row
      if (wanted[j * cw + i] == 0) {
        ++i;
        continue;
      }
      std::size_t end = i + 1;
      while (end < cw && wanted[j * cw + end] != 0)
        ++end;
      skyRunEven(grid, planes, static_cast<int>(2 * j), static_cast<int>(2 * i), end - i,
                 &coarse[j * cw + i]);
      i = end;
    }
  }
  return coarse;
}

} // namespace strahler::layers
