// Layer tiles (issue 28): each derived layer's 256² tile over Mallorca's Serra de Tramuntana at
// z12 and z14, through the tile service, with its cost as a ratio to the 256² Terrain-RGB
// heightmap tile of the same zoom and place timed in the same benchmark (target ≤ 1.5).
// Run with `taskset -c 1 build/release/tests/bench/strahler_layer_bench`.
#include "mallorca_service.h"
#include "web_tiles.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <vector>

namespace strahler {
namespace {

const app::TileService& service() {
  return bench::mallorcaService();
}

constexpr double kLon = bench::kTramuntanaLon, kLat = bench::kTramuntanaLat;

/// This thread's CPU time, ms (a shared machine's other work does not count).
double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

/// The median CPU time of `rounds` renders of `request`, ms.
double medianMs(const app::TileRequest& request, int rounds) {
  std::vector<double> ms;
  for (int k = 0; k < rounds; ++k) {
    const double start = threadCpuMs();
    auto tile = service().render(request);
    benchmark::DoNotOptimize(tile);
    ms.push_back(threadCpuMs() - start);
  }
  std::nth_element(ms.begin(), ms.begin() + rounds / 2, ms.end());
  return ms[static_cast<std::size_t>(rounds / 2)];
}

/// A layer tile per iteration; counters: its bytes, and `vs_heightmap` = the layer tile's
/// median CPU time over the heightmap tile's (both timed here, 15 rounds each, interleaved).
void layerTile(benchmark::State& state, app::LayerName name) {
  const int z = static_cast<int>(state.range(0));
  app::TileRequest layer;
  layer.format = app::TileFormat::kLayerPng;
  layer.tile = test_support::webTileAt(kLon, kLat, z);
  layer.options.layer.name = name;
  if (name == app::LayerName::kHillshade) {
    layer.options.layer.azimuthDeg = 315.0;
    layer.options.layer.altitudeDeg = 45.0;
  }
  app::TileRequest heightmap;
  heightmap.format = app::TileFormat::kTerrainRgb;
  heightmap.tile = layer.tile;
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto tile = service().render(layer);
    if (!tile.ok()) {
      state.SkipWithError(tile.error().message.c_str());
      return;
    }
    bytes = tile.value().bytes.size();
    benchmark::DoNotOptimize(tile);
  }
  double layerMs = 0.0, heightmapMs = 0.0;
  for (int round = 0; round < 3; ++round) { // interleaved, so that both see the same machine
    heightmapMs += medianMs(heightmap, 5);
    layerMs += medianMs(layer, 5);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
  state.counters["vs_heightmap"] = layerMs / heightmapMs;
}

void BM_HeightmapTile(benchmark::State& state) {
  app::TileRequest r;
  r.format = app::TileFormat::kTerrainRgb;
  r.tile = test_support::webTileAt(kLon, kLat, static_cast<int>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(service().render(r));
}

void BM_Slope(benchmark::State& s) {
  layerTile(s, app::LayerName::kSlope);
}
void BM_Aspect(benchmark::State& s) {
  layerTile(s, app::LayerName::kAspect);
}
void BM_Illumination(benchmark::State& s) {
  layerTile(s, app::LayerName::kIllumination);
}
void BM_Hillshade(benchmark::State& s) {
  layerTile(s, app::LayerName::kHillshade);
}
void BM_Humidity(benchmark::State& s) {
  layerTile(s, app::LayerName::kHumidity);
}
void BM_Sediment(benchmark::State& s) {
  layerTile(s, app::LayerName::kSediment);
}
void BM_Vegetation(benchmark::State& s) {
  layerTile(s, app::LayerName::kVegetation);
}
void BM_Water(benchmark::State& s) {
  layerTile(s, app::LayerName::kWater);
}

BENCHMARK(BM_HeightmapTile)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Slope)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Aspect)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Illumination)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Hillshade)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Humidity)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sediment)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Vegetation)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Water)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace strahler
