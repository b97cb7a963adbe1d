// Vector tiles (issue 28): a Mapbox Vector Tile of Mallorca's Serra de Tramuntana at zooms 10,
// 12 and 14 through the tile service (water, contours, rivers, features), its evaluation of the
// 258² contour grid alone, and a 256² Terrain-RGB heightmap tile of the same zoom as the
// baseline of the same run. Run with `taskset -c 1
// build/release/tests/bench/strahler_vector_bench`.
#include "mallorca_service.h"
#include "vector_layers.h"
#include "web_tiles.h"

#include <benchmark/benchmark.h>

namespace strahler {
namespace {

const app::TileService& service() {
  return bench::mallorcaService();
}
constexpr double kLon = bench::kTramuntanaLon, kLat = bench::kTramuntanaLat;

app::TileRequest request(app::TileFormat format, int z) {
  app::TileRequest r;
  r.format = format;
  r.tile = test_support::webTileAt(kLon, kLat, z);
  return r;
}

void render(benchmark::State& state, const app::TileRequest& r) {
  std::string bytes;
  double evaluateMs = 0.0, encodeMs = 0.0;
  for (auto _ : state) {
    auto tile = service().render(r);
    if (!tile.ok()) {
      state.SkipWithError(tile.error().message.c_str());
      return;
    }
    evaluateMs += tile.value().evaluateMs;
    encodeMs += tile.value().encodeMs;
    bytes = std::move(tile).value().bytes;
    benchmark::DoNotOptimize(bytes);
  }
  const auto n = static_cast<double>(state.iterations());
  state.counters["bytes"] = static_cast<double>(bytes.size());
  state.counters["evaluate_ms"] = evaluateMs / n;
  state.counters["layers_ms"] = encodeMs / n;
}

void BM_VectorTile(benchmark::State& state) {
  render(state, request(app::TileFormat::kMvt, static_cast<int>(state.range(0))));
}

void BM_HeightmapTileBaseline(benchmark::State& state) {
  render(state, request(app::TileFormat::kTerrainRgb, static_cast<int>(state.range(0))));
}

BENCHMARK(BM_VectorTile)->Arg(10)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HeightmapTileBaseline)->Arg(10)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace strahler
