// Cesium terrain tiles (issue 26): a z12 quantized-mesh tile over Mallorca's mountains with
// normals and water mask (target ≤ 3 ms on one core), with and without the extensions, beside a
// 256² Terrain-RGB heightmap tile of the same zoom as the baseline of the same run. Run with
// `taskset -c 1 build/release/tests/bench/strahler_cesium_bench`.
#include "mallorca_service.h"
#include "web_tiles.h"

#include "strahler/tiling/water_mask.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace strahler {
namespace {

const app::TileService& service() {
  return bench::mallorcaService();
}
constexpr double kLon = bench::kTramuntanaLon, kLat = bench::kTramuntanaLat;

app::TileRequest terrainRequest(int z, unsigned extensions) {
  const double side = 180.0 / std::ldexp(1.0, z);
  app::TileRequest r;
  r.scheme = tiling::SchemeKind::kGeographic;
  r.format = app::TileFormat::kQuantizedMesh;
  r.tile = {z, static_cast<std::int64_t>((kLon + 180.0) / side),
            static_cast<std::int64_t>((90.0 - kLat) / side)};
  r.options.extensions = extensions;
  return r;
}

void render(benchmark::State& state, const app::TileRequest& request) {
  std::string bytes;
  for (auto _ : state) {
    auto tile = service().render(request);
    if (!tile.ok()) {
      state.SkipWithError(tile.error().message.c_str());
      return;
    }
    bytes = std::move(tile).value().bytes;
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["bytes"] = static_cast<double>(bytes.size());
  if (request.format == app::TileFormat::kQuantizedMesh && bytes.size() >= 92) {
    // vertexCount: the uint32 after the 88-byte header (little-endian), of a 65² grid's 4,225.
    std::uint32_t vertices = 0;
    for (int k = 3; k >= 0; --k)
      vertices =
          vertices << 8 | static_cast<unsigned char>(bytes[88 + static_cast<std::size_t>(k)]);
    state.counters["vertices"] = vertices;
  }
}

void BM_CesiumTerrainAllExtensions(benchmark::State& state) {
  render(state, terrainRequest(static_cast<int>(state.range(0)),
                               app::kOctVertexNormals | app::kWaterMask | app::kMetadata));
}

void BM_CesiumTerrainBare(benchmark::State& state) {
  render(state, terrainRequest(static_cast<int>(state.range(0)), 0));
}

void BM_HeightmapTileBaseline(benchmark::State& state) {
  app::TileRequest r;
  r.format = app::TileFormat::kTerrainRgb;
  r.tile = test_support::webTileAt(kLon, kLat, static_cast<int>(state.range(0)));
  render(state, r);
}

void BM_WaterMask(benchmark::State& state) {
  const app::TileRequest r = terrainRequest(static_cast<int>(state.range(0)), 0);
  const tiling::TileScheme& scheme = service().scheme(tiling::SchemeKind::kGeographic);
  const construction::World& world = service().world();
  const tiling::WaterMask mask(world, geometry::LocalProjection(world.data().projectionCenter.x,
                                                                world.data().projectionCenter.y));
  const geometry::Aabb box = scheme.geographicBounds(r.tile);
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto cells = mask.of(box);
    bytes = cells.size();
    benchmark::DoNotOptimize(cells);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}

BENCHMARK(BM_WaterMask)->Arg(10)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HeightmapTileBaseline)->Arg(12)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CesiumTerrainAllExtensions)
    ->Arg(10)
    ->Arg(12)
    ->Arg(14)
    ->Arg(16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CesiumTerrainBare)->Arg(12)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace strahler
