// The seed's erosion (core/erosion) on export grids of Mallorca: 50 rounds on 1025² and 4097²
// grids (the whole island, 100 km), wall and process CPU time, default parameters, all cores.
// Run with `build/release/tests/bench/strahler_erosion_bench`.
#include "erosion_grid.h"

#include "strahler/erosion/erosion.h"

#include <benchmark/benchmark.h>

namespace strahler {
namespace {

void erodeMallorca(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::vector<double> heights =
      bench::mallorcaGrid(n, bench::kMallorcaLon, bench::kMallorcaLat, bench::kMallorcaSideM);
  const double spacing = bench::kMallorcaSideM / (n - 1);
  erosion::Params params;
  params.iterations = 50;
  int sweeps = 0;
  for (auto _ : state) {
    auto layers = erosion::erode(heights, n, n, spacing, params);
    sweeps = layers.value().finalSweeps;
    benchmark::DoNotOptimize(layers);
  }
  state.counters["final_sweeps"] = sweeps;
}
BENCHMARK(erodeMallorca)
    ->Arg(1025)
    ->Arg(4097)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

} // namespace
} // namespace strahler
