#include "engine_splat.h"

#include "parallel_chunks.h"

#include "strahler/base/smoothstep.h"
#include "strahler/encoding/grey_png.h"
#include "strahler/geometry/projection.h"
#include "strahler/layers/bordered_heights.h"
#include "strahler/layers/humidity.h"
#include "strahler/layers/sediment.h"
#include "strahler/layers/sky_view.h"
#include "strahler/layers/vegetation_density.h"
#include "strahler/tiling/tile_scheme.h"
#include "strahler/tiling/water_mask.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::app {
namespace {

using base::ErrorCode;
using base::makeError;

/// Rows of samples scored at a time by one thread.
constexpr int kBand = 32;
/// The largest side of the PNGs the encoding module writes.
constexpr int kMaxPngSide = 4096;

/// What scoring needs besides the grid: the world, its water mask and its species.
struct ScoringContext {
  const construction::World& world;
  const tiling::WaterMask& water;
  std::vector<layers::Species> species;
};

/// The scores of sample rows [r0, r1) of `g`, row-major. The heights beyond the box repeat
/// its edge samples (the sky view looks SkyView::kReach samples away); the rivers' wetness
/// and the water are the world's at the samples' own points.
std::vector<SplatScores> scoreRows(const ScoringContext& context, const SplatGrid& g, int r0,
                                   int r1) {
  const int n = g.size, rows = r1 - r0, b = layers::SkyView::kReach;
  const double dx = g.box.size().x / (n - 1), dy = g.box.size().y / (n - 1);
  const int w = n + 2 * b, h = rows + 2 * b;
  std::vector<double> heights(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  tiling::SampleGrid bordered, inside;
  bordered.width = w, bordered.height = h;
  inside.width = n, inside.height = rows;
  for (int y = 0; y < h; ++y) {
    const int row = r0 - b + y, sourceRow = std::clamp(row, 0, n - 1);
    for (int x = 0; x < w; ++x) {
      const int column = x - b;
      heights[static_cast<std::size_t>(y) * w + x] =
          g.heights[static_cast<std::size_t>(sourceRow) * n +
                    static_cast<std::size_t>(std::clamp(column, 0, n - 1))];
      const geometry::Vec2 p{g.box.min.x + column * dx, g.box.max.y - row * dy};
      bordered.points.push_back(p);
      bordered.bounds.add(p);
      if (y >= b && y < b + rows && x >= b && x < b + n) {
        inside.points.push_back(p);
        inside.bounds.add(p);
      }
    }
  }
  bordered.rowSpacing.assign(static_cast<std::size_t>(h), std::sqrt(dx * dy));
  inside.rowSpacing.assign(static_cast<std::size_t>(rows), std::sqrt(dx * dy));
  const layers::BorderedHeights grid{heights, n, rows, b, bordered.rowSpacing};
  const std::vector<double> sky = layers::skyView(grid, 1);
  const std::vector<double> humidity =
      layers::humidity(grid, layers::riverWetness(context.world, bordered, b, 1));
  const std::vector<double> proxy =
      g.sediment.empty() ? layers::sedimentThickness(grid) : std::vector<double>();
  const std::vector<std::uint8_t> water = context.water.ofGrid(inside);
  std::vector<SplatScores> out(static_cast<std::size_t>(n) * static_cast<std::size_t>(rows));
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < n; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * n + x;
      const double dzdx = (grid.at(x + 1, y) - grid.at(x - 1, y)) / (2 * dx);
      const double dzdy = (grid.at(x, y - 1) - grid.at(x, y + 1)) / (2 * dy);
      const double slope = std::atan(std::hypot(dzdx, dzdy)) * 180.0 / std::numbers::pi;
      const double sediment =
          g.sediment.empty()
              ? proxy[i]
              : static_cast<double>(
                    g.sediment[static_cast<std::size_t>(r0 + y) * n + static_cast<std::size_t>(x)]);
      const layers::Environment environment{std::max(0.0, sediment), sky[i], humidity[i],
                                            water[i] != 0};
      double density = 0;
      for (const layers::Species& s : context.species)
        density += layers::vegetationDensity(s, environment);
      out[i] = splatScores(slope, sediment, density, water[i] != 0);
    }
  return out;
}

} // namespace

SplatScores splatScores(double slopeDeg, double sedimentM, double vegetation, bool water) noexcept {
  if (water)
    return {0, 0, 0, 0, 1};
  const double rock = base::smoothstep((slopeDeg - kRockFromDeg) / (kRockFullDeg - kRockFromDeg));
  const double sediment = std::clamp(sedimentM / kSedimentFullM, 0.0, 1.0) * (1 - rock);
  const double plants = std::clamp(vegetation, 0.0, 1.0) * (1 - rock);
  const double ground = std::max(0.0, 1 - rock - std::max(sediment, plants));
  return {static_cast<float>(ground), static_cast<float>(rock), static_cast<float>(sediment),
          static_cast<float>(plants), 0.0f};
}

std::array<std::uint8_t, kSplatLayerCount> splatWeights(const SplatScores& scores) noexcept {
  double total = 0;
  for (const float s : scores)
    total += std::max(0.0f, s);
  std::array<std::uint8_t, kSplatLayerCount> out{};
  std::array<double, kSplatLayerCount> fraction{};
  int sum = 0;
  for (int k = 0; k < kSplatLayerCount; ++k) {
    const double share = total > 0 ? std::max(0.0f, scores[k]) / total * 255.0 : (k == 0 ? 255 : 0);
    const double whole = std::floor(share);
    out[k] = static_cast<std::uint8_t>(whole);
    fraction[k] = share - whole;
    sum += out[k];
  }
  for (; sum < 255; ++sum) { // the largest fractional part first, the earlier layer on a tie
    int best = 0;
    for (int k = 1; k < kSplatLayerCount; ++k)
      if (fraction[k] > fraction[best])
        best = k;
    ++out[best];
    fraction[best] = -1;
  }
  return out;
}

base::Status checkSplat(Engine engine, int size, int tilesX, int tilesY) {
  const int side =
      engine == Engine::kUnity ? size - 1 : std::max((size - 1) / tilesX, (size - 1) / tilesY) + 1;
  if (side > kMaxPngSide)
    return makeError(ErrorCode::kInvalidInput,
                     "--splat --size " + std::to_string(size) +
                         ": the weight PNGs hold at most 4096 samples per side (--size 4096 or "
                         "less, or Unreal --tiles; Unity's 4097 gives 4096² alphamaps)");
  return base::Ok{};
}

base::Result<std::vector<SplatFile>> renderSplat(const construction::World& world, Engine engine,
                                                 const SplatGrid& g, int threads,
                                                 std::atomic<long long>& rowsDone, int tilesX,
                                                 int tilesY) {
  const tiling::WaterMask water(world, geometry::LocalProjection(world.data().projectionCenter.x,
                                                                 world.data().projectionCenter.y));
  ScoringContext context{world, water, {}};
  for (std::size_t s = 0; s < layers::kSpecies.size(); ++s)
    context.species.push_back(layers::speciesOf(world.data().params, s));
  const int n = g.size;
  std::vector<SplatFile> files;
  if (engine == Engine::kUnity) { // texel (r, c) covers the quad of samples r..r+1, c..c+1
    const int m = n - 1;
    std::vector<std::uint8_t> maps[2];
    for (auto& map : maps)
      map.assign(static_cast<std::size_t>(m) * m * 4, 0);
    forChunks(0, m, kBand, threads, [&](int r0, int r1) {
      const std::vector<SplatScores> scores = scoreRows(context, g, r0, r1 + 1);
      for (int r = 0; r < r1 - r0; ++r)
        for (int c = 0; c < m; ++c) {
          SplatScores mean{};
          for (const int corner : {r * n + c, r * n + c + 1, (r + 1) * n + c, (r + 1) * n + c + 1})
            for (int k = 0; k < kSplatLayerCount; ++k)
              mean[k] += scores[static_cast<std::size_t>(corner)][k] / 4;
          const auto w = splatWeights(mean);
          const std::size_t at = (static_cast<std::size_t>(r0 + r) * m + c) * 4;
          for (int k = 0; k < kSplatLayerCount; ++k)
            maps[k / 4][at + k % 4] = w[k];
        }
      rowsDone.fetch_add(r1 - r0);
    });
    for (int i = 0; i < 2; ++i) {
      STRAHLER_ASSIGN_OR_RETURN(std::string bytes, encoding::encodeRgba8Png(maps[i], m, m));
      files.push_back({"_alphamap" + std::to_string(i) + ".png", std::move(bytes)});
    }
    return files;
  }
  std::vector<std::vector<std::uint8_t>> layerBytes(kSplatLayerCount);
  for (auto& layer : layerBytes)
    layer.assign(static_cast<std::size_t>(n) * n, 0);
  forChunks(0, n, kBand, threads, [&](int r0, int r1) {
    const std::vector<SplatScores> scores = scoreRows(context, g, r0, r1);
    for (std::size_t i = 0; i < scores.size(); ++i) {
      const auto w = splatWeights(scores[i]);
      for (int k = 0; k < kSplatLayerCount; ++k)
        layerBytes[static_cast<std::size_t>(k)][static_cast<std::size_t>(r0) * n + i] = w[k];
    }
    rowsDone.fetch_add(r1 - r0);
  });
  const int sideX = (n - 1) / tilesX, sideY = (n - 1) / tilesY;
  const bool tiled = tilesX > 1 || tilesY > 1;
  for (int k = 0; k < kSplatLayerCount; ++k) {
    const std::vector<std::uint8_t>& layer = layerBytes[static_cast<std::size_t>(k)];
    const std::string name = std::string("_splat_") + kSplatLayerNames[static_cast<std::size_t>(k)];
    if (!tiled) {
      STRAHLER_ASSIGN_OR_RETURN(std::string bytes, encoding::encodeGrey8Png(layer, n, n));
      files.push_back({name + ".png", std::move(bytes)});
      continue;
    }
    for (int ty = 0; ty < tilesY; ++ty)
      for (int tx = 0; tx < tilesX; ++tx) { // the heightmap's tiles: shared edge samples
        std::vector<std::uint8_t> tile;
        tile.reserve(static_cast<std::size_t>(sideX + 1) * static_cast<std::size_t>(sideY + 1));
        for (int r = ty * sideY; r <= ty * sideY + sideY; ++r)
          for (int c = tx * sideX; c <= tx * sideX + sideX; ++c)
            tile.push_back(layer[static_cast<std::size_t>(r) * n + c]);
        STRAHLER_ASSIGN_OR_RETURN(std::string bytes,
                                  encoding::encodeGrey8Png(tile, sideX + 1, sideY + 1));
        files.push_back({name + "_x" + std::to_string(tx) + "_y" + std::to_string(ty) + ".png",
                         std::move(bytes)});
      }
  }
  return files;
}

} // namespace strahler::app
