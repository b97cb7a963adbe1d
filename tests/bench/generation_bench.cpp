// Per-stage times of world generation (issue: graph + analysis of ~3,500 km² in ≤ 0.3 s on
// one core; 4× the area in ≤ 5× the time). Run: build/release/tests/bench/strahler_bench
#include "test_worlds.h"

#include "strahler/analysis/hydrology.h"
#include "strahler/construction/world.h"
#include "strahler/construction/world_builder.h"
#include "strahler/network/network_growth.h"
#include "strahler/store/world_file.h"

#include <benchmark/benchmark.h>

namespace strahler {
namespace {

/// The world named by the benchmark argument: 0 default island, 1 Mallorca, 2 Mallorca
/// scaled ×2 in each direction (4× the area).
input::WorldSpec worldFor(std::int64_t which) {
  if (which == 0)
    return testing::defaultIslandSpec();
  input::WorldSpec spec = testing::mallorcaSpec();
  if (which == 2)
    for (geometry::Polygon& p : spec.land) {
      for (geometry::Vec2& v : p.outer)
        v = v * 2.0;
      for (geometry::Ring& h : p.holes)
        for (geometry::Vec2& v : h)
          v = v * 2.0;
    }
  return spec;
}

void setLabel(benchmark::State& state, const input::WorldSpec& spec) {
  static const char* names[] = {"default", "mallorca", "mallorca-x4"};
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
  state.counters["bytes/km2"] = static_cast<double>(bytes) / (geometry::area(spec.land) / 1e6);
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
BENCHMARK(BM_LoadWorld)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace strahler
