// Per-stage times of world generation (issue: graph + analysis of ~3,500 km² in ≤ 0.3 s on
// one core; 4× the area in ≤ 5× the time), and the whole generation of Mallorca scaled to
// 4×, 16× and 64× its area (issue 16: cost no worse than n log n; 236,000 km² works).
// Run: build/release/tests/bench/strahler_bench (--benchmark_filter=BM_GenerateWorld for the
// scaling series alone).
#include "test_worlds.h"

#include "strahler/analysis/hydrology.h"
#include "strahler/construction/world.h"
#include "strahler/construction/world_builder.h"
#include "strahler/network/network_growth.h"
#include "strahler/store/world_file.h"

#include <benchmark/benchmark.h>

namespace strahler {
namespace {

/// The world named by the benchmark argument: 0 default island, 1 Mallorca, 2, 3 and 4
/// Mallorca scaled ×2, ×4 and ×8 in each direction (4×, 16× and 64× the area).
input::WorldSpec worldFor(std::int64_t which) {
  if (which == 0)
    return test_support::defaultIslandSpec();
  return test_support::scaledMallorcaSpec(static_cast<double>(std::int64_t{1} << (which - 1)));
}

void setLabel(benchmark::State& state, const input::WorldSpec& spec) {
  static const char* names[] = {"default", "mallorca", "mallorca-x4", "mallorca-x16",
                                "mallorca-x64"};
  state.SetLabel(std::string(names[state.range(0)]) + " " +
                 std::to_string(static_cast<int>(geometry::area(spec.land) / 1e6)) + " km2");
}

void BM_Network(benchmark::State& state) {
  const input::WorldSpec spec = worldFor(state.range(0));
  const geometry::PolygonIndex land(spec.land);
  std::size_t nodes = 0;
  for (auto _ : state) {
    auto net = network::generateNetwork(spec, land);
    nodes = net.value().nodes.size();
    benchmark::DoNotOptimize(net);
  }
  state.counters["nodes"] = static_cast<double>(nodes);
  setLabel(state, spec);
}

void BM_Blocks(benchmark::State& state) {
  const input::WorldSpec spec = worldFor(state.range(0));
  const geometry::PolygonIndex land(spec.land);
  const network::RiverNetwork net = network::generateNetwork(spec, land).value();
  for (auto _ : state)
    benchmark::DoNotOptimize(blocks::buildBlocks(net, land));
  setLabel(state, spec);
}

void BM_Analysis(benchmark::State& state) {
  const input::WorldSpec spec = worldFor(state.range(0));
  const geometry::PolygonIndex land(spec.land);
  const network::RiverNetwork net = network::generateNetwork(spec, land).value();
  const blocks::BlockSet blocks = blocks::buildBlocks(net, land).value();
  for (auto _ : state)
    benchmark::DoNotOptimize(analysis::analyzeNetwork(spec, land, net, blocks));
  setLabel(state, spec);
}

/// The whole first half of the pipeline: what the ≤ 0.3 s target is about.
void BM_GraphPlusAnalysis(benchmark::State& state) {
  const input::WorldSpec spec = worldFor(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(analysis::buildHydrology(spec));
  setLabel(state, spec);
}

BENCHMARK(BM_Network)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Blocks)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Analysis)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GraphPlusAnalysis)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace strahler

namespace strahler {
namespace {

/// The whole generation (graph, analysis, primitives) — target ≤ 1 s for ~3,500 km².
void BM_GenerateWorld(benchmark::State& state) {
  const input::WorldSpec spec = worldFor(state.range(0));
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto world = construction::generateWorldData(spec, "bench");
    bytes = store::encodeWorld(world.value()).size();
    benchmark::DoNotOptimize(bytes);
  }
  const double areaKm2 = geometry::area(spec.land) / 1e6;
  state.counters["bytes/km2"] = static_cast<double>(bytes) / areaKm2;
  // Flat across the series where the cost grows linearly with the area.
  state.counters["km2/s"] =
      benchmark::Counter(areaKm2, benchmark::Counter::kIsIterationInvariantRate);
  setLabel(state, spec);
}

/// Reading a cached world: decode the file and index it for evaluation — target ≤ 50 ms.
void BM_LoadWorld(benchmark::State& state) {
  const input::WorldSpec spec = worldFor(state.range(0));
  const std::string bytes =
      store::encodeWorld(construction::generateWorldData(spec, "bench").value());
  for (auto _ : state) {
    auto data = store::decodeWorld(bytes, "bench");
    const construction::World world(std::move(data).value());
    benchmark::DoNotOptimize(world.data().terrain.size());
  }
  setLabel(state, spec);
}

BENCHMARK(BM_GenerateWorld)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GenerateWorld)->DenseRange(3, 4)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadWorld)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace strahler
