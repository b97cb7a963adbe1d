// Tile evaluation cost (issue "Tiles"): samples per second per core for 256² heightmap tiles at
// zoom 0, a middle zoom and the finest zoom, and the same tiles evaluated without the block
// restriction, in one run. Run: build/release/tests/bench/strahler_tile_bench
#include "test_worlds.h"
#include "web_tiles.h"

#include "strahler/construction/world_builder.h"
#include "strahler/tiling/tile_evaluator.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

namespace strahler {
namespace {

struct Fixture {
  construction::World world;
  tiling::TileEvaluator evaluator;
  tiling::TileScheme web;
  explicit Fixture(construction::WorldData data)
      : world(std::move(data)), evaluator(world),
        web(tiling::TileScheme::webMercator(geometry::LocalProjection(
            world.data().projectionCenter.x, world.data().projectionCenter.y))) {}
};

const Fixture& fixture() {
  static const Fixture f(
      construction::generateWorldData(test_support::mallorcaSpec(), "bench").value());
  return f;
}

/// Mallorca scaled ×4 in each direction: 58,000 km², 16 times the area (and the primitives).
const Fixture& largeFixture() {
  static const Fixture f(
      construction::generateWorldData(test_support::scaledMallorcaSpec(4.0), "bench-x16").value());
  return f;
}

/// A web tile over land at zoom z (Mallorca's centre).
geometry::TileId tileAt(int z) {
  const geometry::Vec2 c = fixture().world.data().projectionCenter;
  return test_support::webTileAt(c.x, c.y, z);
}

void BM_TileRestricted(benchmark::State& state) {
  const Fixture& f = fixture();
  const tiling::SampleGrid grid = f.web.rasterGrid(tileAt(static_cast<int>(state.range(0))), 256);
  for (auto _ : state)
    benchmark::DoNotOptimize(f.evaluator.evaluate(grid));
  state.counters["samples/s"] = benchmark::Counter(static_cast<double>(grid.points.size()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

/// BM_TileRestricted on a narrower instruction set than the CPU's widest (range(1): 0 SSE2,
/// 1 AVX2), for machines without AVX-512; skipped where the CPU lacks it.
void BM_TileRestrictedOn(benchmark::State& state) {
  const Fixture& f = fixture();
  const simd::InstructionSet saved = simd::instructionSet();
  const auto set =
      state.range(1) == 0 ? simd::InstructionSet::kBaseline : simd::InstructionSet::kAvx2;
  if (!simd::useInstructionSet(set)) {
    state.SkipWithError("the CPU lacks this instruction set");
    return;
  }
  const tiling::SampleGrid grid = f.web.rasterGrid(tileAt(static_cast<int>(state.range(0))), 256);
  for (auto _ : state)
    benchmark::DoNotOptimize(f.evaluator.evaluate(grid));
  simd::useInstructionSet(saved);
  state.counters["samples/s"] = benchmark::Counter(static_cast<double>(grid.points.size()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

/// The same samples through the whole-world evaluator (World::height, its uniform grid).
void BM_TileWholeWorld(benchmark::State& state) {
  const Fixture& f = fixture();
  const tiling::SampleGrid grid = f.web.rasterGrid(tileAt(static_cast<int>(state.range(0))), 256);
  for (auto _ : state)
    for (std::size_t k = 0; k < grid.points.size(); ++k)
      benchmark::DoNotOptimize(f.world.height(grid.points[k], grid.rowSpacing[k / 256]));
  state.counters["samples/s"] = benchmark::Counter(static_cast<double>(grid.points.size()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

/// Naive: every primitive of the world considered for every sample (16×16 samples only).
void BM_TileAllPrimitives(benchmark::State& state) {
  const Fixture& f = fixture();
  const tiling::SampleGrid grid = f.web.rasterGrid(tileAt(static_cast<int>(state.range(0))), 16);
  std::vector<std::uint32_t> terrain(f.world.data().terrain.size());
  std::iota(terrain.begin(), terrain.end(), 0u);
  std::vector<construction::World::RiverCandidate> rivers;
  for (std::uint32_t i = 0; i < f.world.data().rivers.size(); ++i)
    rivers.push_back(f.world.wholeRiver(base::PrimitiveId(i)));
  for (auto _ : state)
    for (std::size_t k = 0; k < grid.points.size(); ++k)
      benchmark::DoNotOptimize(
          f.world.evaluateFrom(grid.points[k], grid.rowSpacing[k / 16], terrain, rivers));
  state.counters["samples/s"] = benchmark::Counter(static_cast<double>(grid.points.size()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

/// The median over the 3×3 tiles around the island's centre at zoom range(0) (what a viewer
/// there loads): each tile's median of range(1) evaluations, tiles interleaved so that the
/// machine's drift hits them alike and each evaluation finds the caches as the others left
/// them; each tile's grid is built just before its evaluation, as a server does (not timed).
/// Reported per tile: the centre's ("centre_ms"), the median and the dearest tile's.
void BM_TileNeighbourhood(benchmark::State& state) {
  const Fixture& f = fixture();
  const int z = static_cast<int>(state.range(0));
  const geometry::TileId centre = tileAt(z);
  std::vector<geometry::TileId> tiles;
  std::size_t centreIndex = 0;
  for (std::int64_t dy = -1; dy <= 1; ++dy)
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      const geometry::TileId t{z, centre.x + dx, centre.y + dy};
      if (!f.web.contains(t))
        continue;
      if (dx == 0 && dy == 0)
        centreIndex = tiles.size();
      tiles.push_back(t);
    }
  std::vector<std::vector<double>> ms(tiles.size());
  for (auto _ : state)
    for (std::int64_t r = 0; r < state.range(1); ++r)
      for (std::size_t t = 0; t < tiles.size(); ++t) {
        const tiling::SampleGrid grid = f.web.rasterGrid(tiles[t], 256);
        const auto start = std::chrono::steady_clock::now();
        benchmark::DoNotOptimize(f.evaluator.evaluate(grid));
        ms[t].push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
      }
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  std::vector<double> perTile;
  for (const std::vector<double>& m : ms)
    perTile.push_back(median(m));
  state.counters["centre_ms"] = perTile[centreIndex];
  state.counters["median_ms"] = median(perTile);
  state.counters["max_ms"] = *std::max_element(perTile.begin(), perTile.end());
}

/// A fixed number of tiles (range(1)) at zoom range(0) in one iteration, for counting with
/// perf: scripts/bench/tile-counters.sh subtracts the run with 0 tiles (world generation and
/// start-up), which Google Benchmark's own timing cannot do for a whole process. The
/// environment variable STRAHLER_BENCH_SET=avx2 or sse2 evaluates with that instruction set.
void BM_TileFixedCount(benchmark::State& state) {
  const Fixture& f = fixture();
  if (const char* set = std::getenv("STRAHLER_BENCH_SET")) {
    const std::string name(set);
    const bool known = name == "avx2" || name == "sse2";
    if (!known || !simd::useInstructionSet(name == "avx2" ? simd::InstructionSet::kAvx2
                                                          : simd::InstructionSet::kBaseline)) {
      state.SkipWithError("STRAHLER_BENCH_SET: avx2 or sse2, and one this CPU has");
      return;
    }
  }
  const tiling::SampleGrid grid = f.web.rasterGrid(tileAt(static_cast<int>(state.range(0))), 256);
  for (auto _ : state)
    for (std::int64_t i = 0; i < state.range(1); ++i)
      benchmark::DoNotOptimize(f.evaluator.evaluate(grid));
}

/// Tiles of a large world against the same tiles of Mallorca, in one run (issue 16: the block
/// index keeps a tile's cost local). range(0) zoom, range(1) 1 for Mallorca ×16, 0 for Mallorca;
/// the tile is the one holding the local frame's centre, land in both.
void BM_TileWorldSize(benchmark::State& state) {
  const Fixture& f = state.range(1) == 1 ? largeFixture() : fixture();
  const geometry::Vec2 c = f.world.data().projectionCenter;
  const geometry::TileId tile = test_support::webTileAt(c.x, c.y, static_cast<int>(state.range(0)));
  const tiling::SampleGrid grid = f.web.rasterGrid(tile, 256);
  for (auto _ : state)
    benchmark::DoNotOptimize(f.evaluator.evaluate(grid));
  state.SetLabel(std::to_string(f.world.data().terrain.size()) + " terrain primitives");
}

// Zoom 0 is the whole Earth (Mallorca a few pixels), 9 holds all of Mallorca, 13 is a
// middle zoom, 18 the finest; restricted evaluation also at every zoom from 8 to 13, where the
// cost peaks.
BENCHMARK(BM_TileRestricted)
    ->DenseRange(8, 13)
    ->Arg(0)
    ->Arg(5)
    ->Arg(15)
    ->Arg(18)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TileRestrictedOn)
    ->ArgsProduct({{0, 9, 13, 18}, {0, 1}})
    ->ArgNames({"zoom", "avx2"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TileWorldSize)
    ->ArgsProduct({{11, 12, 13, 14}, {0, 1}})
    ->ArgNames({"zoom", "x16"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TileWholeWorld)->Arg(0)->Arg(9)->Arg(13)->Arg(18)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TileAllPrimitives)->Arg(13)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TileNeighbourhood)
    ->ArgsProduct({{0, 5, 8, 9, 10, 11, 12, 13, 15, 18}, {15}})
    ->ArgNames({"zoom", "runs"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TileFixedCount)
    ->ArgsProduct({{0, 5, 8, 9, 10, 11, 13, 18}, {0, 300}})
    ->ArgNames({"zoom", "tiles"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

} // namespace
} // namespace strahler
