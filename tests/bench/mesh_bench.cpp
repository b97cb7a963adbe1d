// Mesh tile costs: building the grid mesh, Draco (.drc) and glTF (.glb) encoding, for
// 65×65 and 257×257 vertices (target: a 65×65 Draco tile, mesh + encoding, in ≤ 2 ms on one
// core). Run: build/release/tests/bench/strahler_mesh_bench
#include "synthetic_terrain.h"

#include "strahler/encoding/mesh.h"
#include "strahler/encoding/mesh_encoder.h"

#include <benchmark/benchmark.h>

#include <string>

namespace strahler::encoding {
namespace {

MeshGridInput tileInput(benchmark::State& state) {
  const int quads = static_cast<int>(state.range(0));
  // A 1.92 km tile at n = 64 (30 m spacing), the same extent at n = 256.
  return testing::syntheticTile(quads, 1920.0 / quads, {3840.0, -1920.0}, 50.0, true);
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

} // namespace
} // namespace strahler::encoding
