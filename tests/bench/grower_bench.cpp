// The two river-network growers side by side (issue 30): the grammar (Section 4.2) and the
// diffusion-limited aggregation of seed 001, on Mallorca and Corsica, one core. Per grower and
// world: the network's CPU time (target for DLA on Mallorca: ≤ 1 s), its nodes, Horton Rb and
// Rl, the fractal dimension ln Rb / ln Rl, the coverage (farthest land from a river, km), and
// for DLA its CPU time over the grammar's timed in the same benchmark (`vs_grammar`).
// Run with `taskset -c 1 build/release/tests/bench/strahler_grower_bench`.
#include "test_worlds.h"

#include "strahler/network/network_growth.h"
#include "strahler/quality/horton.h"
#include "strahler/quality/network_coverage.h"

#include <benchmark/benchmark.h>

#include <ctime>

namespace strahler {
namespace {

/// This thread's CPU time, ms (a shared machine's other work does not count).
double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

input::WorldSpec worldFor(std::int64_t which, input::NetworkGrower grower) {
  input::WorldSpec spec = which == 0 ? test_support::mallorcaSpec() : test_support::corsicaSpec();
  spec.params.grower = grower;
  return spec;
}

/// CPU ms of one network of `spec`.
double networkMs(const input::WorldSpec& spec, const geometry::PolygonIndex& land) {
  const double start = threadCpuMs();
  auto net = network::generateNetwork(spec, land);
  benchmark::DoNotOptimize(net);
  return threadCpuMs() - start;
}

/// Range 0: the world (0 Mallorca, 1 Corsica); range 1: the grower (0 grammar, 1 DLA).
void BM_Grower(benchmark::State& state) {
  const auto grower =
      state.range(1) == 0 ? input::NetworkGrower::kGrammar : input::NetworkGrower::kDla;
  const input::WorldSpec spec = worldFor(state.range(0), grower);
  const geometry::PolygonIndex land(spec.land);
  network::RiverNetwork net;
  for (auto _ : state) {
    auto grown = network::generateNetwork(spec, land);
    if (!grown.ok()) {
      state.SkipWithError(grown.error().message.c_str());
      return;
    }
    net = std::move(grown).value();
  }
  const quality::HortonStatistics horton = quality::hortonStatistics(net);
  const quality::NetworkCoverage coverage = quality::networkCoverage(net, land);
  state.counters["nodes"] = static_cast<double>(net.nodes.size());
  state.counters["mouths"] = static_cast<double>(net.mouths.size());
  state.counters["orders"] = static_cast<double>(horton.streamCount.size() - 1);
  state.counters["Rb"] = horton.bifurcationRatio;
  state.counters["Rl"] = horton.lengthRatio;
  state.counters["D"] = horton.fractalDimension;
  state.counters["coverage_km"] = coverage.farthestM / 1000.0;
  state.counters["over3km"] = coverage.fartherThan3KmFraction;
  if (grower == input::NetworkGrower::kDla) {
    const input::WorldSpec grammar = worldFor(state.range(0), input::NetworkGrower::kGrammar);
    double dlaMs = 0.0, grammarMs = 0.0;
    for (int round = 0; round < 3; ++round) { // interleaved, so that both see the same machine
      grammarMs += networkMs(grammar, land);
      dlaMs += networkMs(spec, land);
    }
    state.counters["cpu_ms"] = dlaMs / 3.0;
    state.counters["vs_grammar"] = dlaMs / grammarMs;
  } else {
    state.counters["cpu_ms"] = networkMs(spec, land);
  }
  state.SetLabel(std::string(state.range(0) == 0 ? "mallorca " : "corsica ") +
                 (grower == input::NetworkGrower::kDla ? "dla" : "grammar"));
}

BENCHMARK(BM_Grower)
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

} // namespace
} // namespace strahler
