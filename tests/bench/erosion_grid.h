#pragma once
// A square height grid over Mallorca, as the heightmap export samples it, for the erosion
// benchmark and picture.

#include "test_worlds.h"

#include "strahler/construction/world.h"
#include "strahler/construction/world_builder.h"
#include "strahler/geometry/projection.h"
#include "strahler/tiling/tile_evaluator.h"

#include <vector>

namespace strahler::bench {

/// Mallorca's world, generated once per process.
inline const construction::World& mallorcaWorld() {
  static const construction::World world(
      construction::generateWorldData(test_support::mallorcaSpec(), "bench").value());
  return world;
}

/// `n` × `n` heights (row-major, north row first) of a square `sideM` metres wide centred on
/// (lon, lat), spacing sideM / (n − 1), evaluated with tiling::TileEvaluator.
inline std::vector<double> mallorcaGrid(int n, double lon, double lat, double sideM) {
  const construction::World& world = mallorcaWorld();
  const geometry::Vec2 c = world.data().projectionCenter;
  const geometry::Vec2 centre = geometry::LocalProjection(c.x, c.y).forward({lon, lat});
  const double spacing = sideM / (n - 1);
  tiling::SampleGrid grid;
  grid.width = n;
  grid.height = n;
  grid.rowSpacing.assign(static_cast<std::size_t>(n), spacing);
  grid.points.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const geometry::Vec2 p{centre.x - sideM / 2 + x * spacing,
                             centre.y + sideM / 2 - y * spacing};
      grid.points.push_back(p);
      grid.bounds.add(p);
    }
  return tiling::TileEvaluator(world).evaluate(grid);
}

/// The Serra de Tramuntana's centre (mallorca_service.h's kTramuntana*, without the app).
inline constexpr double kSerraLon = 2.75, kSerraLat = 39.78;

/// Mallorca's centre and a side holding the whole island, for the export-sized benchmark.
inline constexpr double kMallorcaLon = 2.98, kMallorcaLat = 39.62, kMallorcaSideM = 100000.0;

} // namespace strahler::bench
