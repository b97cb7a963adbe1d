// quantized-mesh-1.0 tile costs: RTIN meshing plus encoding of a 65×65 grid with oct normals and
// a 256×256 water mask, at Cesium's geometric error of the tile's level (target: a z12 terrain
// tile with normals and water mask in ≤ 3 ms on one core including evaluation, so the encoder
// well under 1 ms). Counters: vertices against the 4,225 of the full grid, bytes, and the
// measured mesh error. Run: taskset -c 1 build/release/tests/bench/strahler_quantized_mesh_bench
#include "synthetic_terrain.h"

#include "strahler/encoding/quantized_mesh.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace strahler::encoding {
namespace {

constexpr int kSamples = 65;

/// The level-`level` geographic tile at 39.6°N 2.9°E (Mallorca), heights from the synthetic
/// terrain over the tile's local metres (the same hills, ridges and detail as mesh_bench).
QuantizedMeshGrid tileGrid(int level) {
  const double size = 180.0 / std::ldexp(1.0, level);
  const double west = -180.0 + std::floor((2.9 + 180.0) / size) * size;
  const double south = -90.0 + std::floor((39.6 + 90.0) / size) * size;
  QuantizedMeshGrid grid;
  grid.rect = {west, south, west + size, south + size};
  grid.samples = kSamples;
  const double metresPerDegree = 111320.0;
  const double spacingY = size / (kSamples - 1) * metresPerDegree;
  const double spacingX = spacingY * std::cos(39.6 * 3.14159265358979 / 180.0);
  for (int j = -1; j <= kSamples; ++j)
    for (int i = -1; i <= kSamples; ++i)
      grid.heights.push_back(test_support::syntheticHeight(i * spacingX, j * spacingY));
  return grid;
}

QuantizedMeshOptions tileOptions(int level) {
  QuantizedMeshOptions options;
  options.maxError = cesiumLevelGeometricError(level);
  options.normals = true;
  options.waterMask.resize(256 * 256);
  for (int row = 0; row < 256; ++row)
    for (int column = 0; column < 256; ++column)
      options.waterMask[static_cast<std::size_t>(row * 256 + column)] =
          column + row < 120 ? 255 : 0;
  return options;
}

void BM_QuantizedMeshTile(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  const QuantizedMeshGrid grid = tileGrid(level);
  const QuantizedMeshOptions options = tileOptions(level);
  QuantizedMeshStats stats;
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto tile = encodeQuantizedMesh(grid, options, &stats);
    if (!tile.ok()) {
      state.SkipWithError(tile.error().message.c_str());
      return;
    }
    bytes = tile.value().size();
    benchmark::DoNotOptimize(tile);
  }
  state.counters["vertices"] = static_cast<double>(stats.vertices);
  state.counters["of_grid"] = static_cast<double>(stats.vertices) / (kSamples * kSamples);
  state.counters["bytes"] = static_cast<double>(bytes);
  state.counters["error_m"] = stats.maxError;
  state.counters["limit_m"] = options.maxError;
}

void BM_EllipsoidTile(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  const double size = 180.0 / std::ldexp(1.0, level);
  QuantizedMeshOptions options;
  options.maxError = cesiumLevelGeometricError(level);
  options.normals = true;
  options.waterMask = {255};
  const GeographicRect rect{0.0, -90.0, size, -90.0 + size};
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto tile = encodeEllipsoidTile(rect, options);
    if (!tile.ok()) {
      state.SkipWithError(tile.error().message.c_str());
      return;
    }
    bytes = tile.value().size();
    benchmark::DoNotOptimize(tile);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}

BENCHMARK(BM_QuantizedMeshTile)
    ->ArgName("level")
    ->Arg(8)
    ->Arg(10)
    ->Arg(12)
    ->Arg(14)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EllipsoidTile)->ArgName("level")->Arg(0)->Arg(12)->Unit(benchmark::kMicrosecond);

} // namespace
} // namespace strahler::encoding
