// Vegetation tiles (issue 28): one z16 (trees) and one z17 (trees and bushes) JSON tile over
// Mallorca's Serra de Tramuntana through the tile service: the lattice's heights and layers,
// the placement and the JSON. Run with `taskset -c 1
// build/release/tests/bench/strahler_vegetation_tile_bench`.
#include "mallorca_service.h"
#include "web_tiles.h"

#include <benchmark/benchmark.h>

#include <string>

namespace strahler {
namespace {

const app::TileService& service() {
  return bench::mallorcaService();
}

/// A valley of the Serra de Tramuntana's southern slope (trees and bushes).
constexpr double kLon = 2.70, kLat = 39.74;

/// One vegetation tile per iteration at zoom state.range(0); counters: its bytes and instances,
/// the evaluation's share (the lattice block's heights) in ms.
void BM_VegetationTile(benchmark::State& state) {
  app::TileRequest request;
  request.format = app::TileFormat::kVegetationJson;
  request.tile = test_support::webTileAt(kLon, kLat, static_cast<int>(state.range(0)));
  double bytes = 0.0, instances = 0.0, evaluateMs = 0.0;
  for (auto _ : state) {
    auto tile = service().render(request);
    if (!tile.ok()) {
      state.SkipWithError(tile.error().message.c_str());
      return;
    }
    const std::string& body = tile.value().bytes;
    bytes = static_cast<double>(body.size());
    instances = 0.0;
    for (std::size_t at = body.find("\"species\":", body.find("\"instances\""));
         at != std::string::npos; at = body.find("\"species\":", at + 1))
      instances += 1.0;
    evaluateMs = tile.value().evaluateMs;
  }
  state.counters["bytes"] = bytes;
  state.counters["instances"] = instances;
  state.counters["evaluate_ms"] = evaluateMs;
}
BENCHMARK(BM_VegetationTile)->Arg(16)->Arg(17)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace strahler
