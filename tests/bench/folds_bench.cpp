// The cost of the tectonic folds (issue 27): zoom 12 256² heightmap tiles over Corsica's drawn
// mountains (Monte d'Oro and the 24 tiles around it), with the folds and without them (the same
// world data, its mountains cleared). Run: build/release/tests/bench/strahler_folds_bench
#include "test_worlds.h"
#include "web_tiles.h"

#include "strahler/construction/world.h"
#include "strahler/construction/world_builder.h"
#include "strahler/tiling/tile_evaluator.h"

#include <benchmark/benchmark.h>

#include <utility>
#include <vector>

namespace strahler {
namespace {

using geometry::Vec2;

/// Monte d'Oro, where the folds are (folds_test.cpp's fixture draws five peaks).
constexpr double kOroLon = 9.1003, kOroLat = 42.1556;

input::WorldSpec corsicaWithMountains() {
  input::WorldSpec spec = test_support::corsicaSpec();
  const struct {
    double lon, lat, elevation;
  } peaks[] = {{8.9456, 42.3797, 2706.0},
               {9.0567, 42.2178, 2622.0},
               {kOroLon, kOroLat, 2389.0},
               {9.1306, 42.0711, 2352.0},
               {9.2028, 41.8553, 2134.0}};
  for (const auto& p : peaks)
    spec.features.mountains.push_back(
        {{p.lon, p.lat}, spec.projection.forward({p.lon, p.lat}), p.elevation, std::nullopt});
  return spec;
}

const construction::WorldData& foldedData() {
  static const construction::WorldData data =
      construction::generateWorldData(corsicaWithMountains(), "folds-bench").value();
  return data;
}

/// The 25 zoom-12 tiles around Monte d'Oro.
std::vector<tiling::SampleGrid> grids() {
  const Vec2 c = foldedData().projectionCenter;
  const tiling::TileScheme web =
      tiling::TileScheme::webMercator(geometry::LocalProjection(c.x, c.y));
  const geometry::TileId centre = test_support::webTileAt(kOroLon, kOroLat, 12);
  std::vector<tiling::SampleGrid> out;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx)
      out.push_back(web.rasterGrid({12, centre.x + dx, centre.y + dy}, 256));
  return out;
}

void runTiles(benchmark::State& state, const construction::World& world) {
  const tiling::TileEvaluator evaluator(world);
  const std::vector<tiling::SampleGrid> tiles = grids();
  for (auto _ : state)
    for (const tiling::SampleGrid& g : tiles)
      benchmark::DoNotOptimize(evaluator.evaluate(g));
  state.counters["tiles/s"] = benchmark::Counter(static_cast<double>(tiles.size()),
                                                 benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Zoom12TileWithFolds(benchmark::State& state) {
  static const construction::World world(foldedData());
  runTiles(state, world);
}
BENCHMARK(BM_Zoom12TileWithFolds)->Unit(benchmark::kMillisecond);

void BM_Zoom12TileWithoutFolds(benchmark::State& state) {
  static const construction::World world = [] {
    construction::WorldData data = foldedData();
    data.features.mountains.clear();
    return construction::World(std::move(data));
  }();
  runTiles(state, world);
}
BENCHMARK(BM_Zoom12TileWithoutFolds)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace strahler
