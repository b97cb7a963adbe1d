// Mesh tile costs: building the grid mesh, Draco (.drc) and glTF (.glb) encoding, for
// 65×65 and 257×257 vertices (target: a 65×65 Draco tile, mesh + encoding, in ≤ 2 ms on one
// core), on synthetic terrain at a fixed 1 cm error and on the default world's tiles as the
// server makes them. Run: build/release/tests/bench/strahler_mesh_bench
#include "synthetic_terrain.h"
#include "test_worlds.h"
#include "tile_service.h"
#include "web_tiles.h"

#include "strahler/construction/world_builder.h"
#include "strahler/encoding/mesh.h"
#include "strahler/encoding/mesh_encoder.h"

#include <benchmark/benchmark.h>

#include <string>

namespace strahler::encoding {
namespace {

MeshGridInput tileInput(benchmark::State& state) {
  const int quads = static_cast<int>(state.range(0));
  // A 1.92 km tile at n = 64 (30 m spacing), the same extent at n = 256.
  return test_support::syntheticTile(quads, 1920.0 / quads, {3840.0, -1920.0}, 50.0, true);
}

Mesh tileMesh(benchmark::State& state) {
  auto mesh = buildGridMesh(tileInput(state));
  if (!mesh.ok())
    state.SkipWithError(mesh.error().message.c_str());
  return mesh.ok() ? std::move(mesh).value() : Mesh{};
}

DracoOptions optionsFor(benchmark::State& state) {
  DracoOptions options;
  options.speed = static_cast<int>(state.range(1));
  return options;
}

void reportBytes(benchmark::State& state, const base::Result<std::string>& bytes) {
  if (!bytes.ok()) {
    state.SkipWithError(bytes.error().message.c_str());
    return;
  }
  state.counters["bytes"] = static_cast<double>(bytes.value().size());
}

void BM_BuildGridMesh(benchmark::State& state) {
  const MeshGridInput input = tileInput(state);
  for (auto _ : state)
    benchmark::DoNotOptimize(buildGridMesh(input));
}

void BM_EncodeDraco(benchmark::State& state) {
  const Mesh mesh = tileMesh(state);
  const DracoOptions options = optionsFor(state);
  for (auto _ : state)
    benchmark::DoNotOptimize(encodeDraco(mesh, options));
  reportBytes(state, encodeDraco(mesh, options));
}

void BM_EncodeGlb(benchmark::State& state) {
  const Mesh mesh = tileMesh(state);
  const DracoOptions options = optionsFor(state);
  for (auto _ : state)
    benchmark::DoNotOptimize(encodeGlb(mesh, options));
  reportBytes(state, encodeGlb(mesh, options));
}

/// What a .drc tile request costs after evaluation: mesh plus encoding.
void BM_DracoTile(benchmark::State& state) {
  const MeshGridInput input = tileInput(state);
  const DracoOptions options = optionsFor(state);
  for (auto _ : state) {
    auto mesh = buildGridMesh(input);
    benchmark::DoNotOptimize(encodeDraco(mesh.value(), options));
  }
}

/// A served .drc tile of the default world (Mallorca) at zoom range(0), 64 quads, over the
/// island's centre: the time is what the server reports for mesh building and Draco encoding
/// (RenderedTile::encodeMs: the position error it serves, max(1 cm, spacing / 1000), and its
/// skirt), not the evaluation before them.
void BM_ServedDracoTile(benchmark::State& state) {
  static const app::TileService service(
      construction::generateWorldData(strahler::test_support::mallorcaSpec(), "bench").value());
  const int z = static_cast<int>(state.range(0));
  const geometry::Vec2 c = service.world().data().projectionCenter;
  app::TileRequest request;
  request.tile = strahler::test_support::webTileAt(c.x, c.y, z);
  request.format = app::TileFormat::kDraco;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto tile = service.render(request);
    if (!tile.ok()) {
      state.SkipWithError(tile.error().message.c_str());
      return;
    }
    state.SetIterationTime(tile.value().encodeMs / 1000.0);
    bytes = tile.value().bytes.size();
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}

void speeds(benchmark::internal::Benchmark* b) {
  b->ArgNames({"n", "speed"});
  for (int quads : {64, 256})
    for (int speed : {0, 5, 7, 10})
      b->Args({quads, speed});
}

BENCHMARK(BM_BuildGridMesh)->ArgName("n")->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EncodeDraco)->Apply(speeds)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EncodeGlb)->Apply(speeds)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DracoTile)->Apply(speeds)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ServedDracoTile)
    ->ArgName("zoom")
    ->Arg(9)
    ->Arg(13)
    ->Arg(18)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);

} // namespace
} // namespace strahler::encoding
