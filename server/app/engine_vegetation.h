#pragma once
// `strahler export-heightmap --vegetation csv|json`: the plants the vegetation tiles serve
// (core/vegetation, placed on the zoom-16 density lattice) inside the export's box, in the
// engine's units and axes, standing on the exported heightmap.

#include "engine_heightmap.h"

#include "strahler/base/result.h"
#include "strahler/construction/world.h"
#include "strahler/geometry/aabb.h"
#include "strahler/tiling/tile_evaluator.h"

#include <array>
#include <atomic>
#include <ostream>
#include <span>
#include <string>

namespace strahler::app {

/// The instance file's format.
enum class VegetationFormat {
  kCsv,  ///< A header line, then one line per plant.
  kJson, ///< {"instances": [{...}, ...]}.
};

/// Parses --vegetation: "csv" or "json".
base::Result<VegetationFormat> parseVegetationFormat(const std::string& name);

/// The Web Mercator zoom whose vegetation tiles are exported: every species is served there.
inline constexpr int kVegetationZoom = 17;

/// The exported grid the plants stand on.
struct VegetationGrid {
  geometry::Aabb box;             ///< Local metres; sample (0, 0) at (min.x, max.y).
  int size = 0;                   ///< Samples per side.
  std::span<const float> heights; ///< size², row 0 north, m (eroded with --erode).
};

/// The ground height at local point `p` inside the box: bilinear between the grid's samples, m.
double heightOnGrid(const VegetationGrid& grid, geometry::Vec2 p) noexcept;

/// A plant's position in `engine`'s frame from its local point `p` and ground height `z` (m):
/// Unity metres (x east, y up, z north; origin the terrain's south-west corner), Unreal
/// centimetres (X east, Y south, Z up; origin the landscape's north-west corner, the first
/// heightmap sample), Godot metres (x east, y up, z south = −z north; origin the north-west
/// corner), raw the world's local metres (x east, y north, z up).
std::array<double, 3> engineCoordinates(Engine engine, const geometry::Aabb& box, geometry::Vec2 p,
                                        double z) noexcept;

/// What writeVegetation() wrote.
struct VegetationCount {
  long long instances = 0; ///< Plants written.
  long long tiles = 0;     ///< Vegetation tiles placed.
};

/// Writes the plants of the zoom-kVegetationZoom vegetation tiles (the served ones) whose
/// position lies in the box to `out`, one tile row at a time (north to south, tiles west to
/// east, each in its canonical order) so that memory stays bounded; the heights come from
/// `grid`. `tileRowsTotal` is set first, `tileRowsDone` counts rows. Same bytes for any
/// `threads`. Stops (kInternal "interrupted") when `stop` returns true between rows.
base::Result<VegetationCount> writeVegetation(const construction::World& world,
                                              const tiling::TileEvaluator& evaluator, Engine engine,
                                              VegetationFormat format, const VegetationGrid& grid,
                                              int threads, std::ostream& out,
                                              std::atomic<long long>& tileRowsTotal,
                                              std::atomic<long long>& tileRowsDone, bool (*stop)());

} // namespace strahler::app
