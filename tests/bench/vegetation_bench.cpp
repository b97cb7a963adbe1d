// Vegetation instances (issue 28): one 256 m tile of trees and bushes at a typical density,
// its border included, with and without the growth simulation, and the tile's JSON.
// Run: taskset -c 1 build/release/tests/bench/strahler_vegetation_bench --benchmark_repetitions=3
#include "strahler/vegetation/placement.h"
#include "strahler/vegetation/vegetation_json.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace strahler::vegetation {
namespace {

/// A density that varies over tens of metres around 0.5 (the "typical" density), per species.
const FunctionDensity& typicalDensity() {
  static const FunctionDensity field([](std::size_t species, geometry::Vec2 p) {
    const double phase = static_cast<double>(species);
    return static_cast<float>(0.5 + 0.4 * std::sin(p.x / 37.0 + phase) * std::cos(p.y / 53.0));
  });
  return field;
}

const Footprint& tile256() {
  static const Footprint f = Footprint::box({{1000.0, 2000.0}, {1256.0, 2256.0}});
  return f;
}

void runTile(benchmark::State& state, PlacementRules rules) {
  std::size_t count = 0;
  for (auto _ : state) {
    const auto instances = placeInstances(42, tile256(), typicalDensity(), kAllSpecies, rules);
    count = instances.size();
    benchmark::DoNotOptimize(instances.data());
  }
  state.counters["instances"] = static_cast<double>(count);
}

void BM_VegetationTile256(benchmark::State& state) {
  runTile(state, PlacementRules{});
}
BENCHMARK(BM_VegetationTile256)->Unit(benchmark::kMillisecond);

void BM_VegetationTile256NoGrowth(benchmark::State& state) {
  runTile(state, PlacementRules{4, 0});
}
BENCHMARK(BM_VegetationTile256NoGrowth)->Unit(benchmark::kMillisecond);

void BM_VegetationJson(benchmark::State& state) {
  const geometry::LocalProjection projection(7.5, 46.5);
  const geometry::TileId tile{17, 68000, 46000}; // the bytes, not the tile's position, are measured
  const auto instances = placeInstances(42, tile256(), typicalDensity(), kAllSpecies);
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string json = writeVegetationJson(tile, projection, instances);
    bytes = json.size();
    benchmark::DoNotOptimize(json.data());
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_VegetationJson)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace strahler::vegetation
