#pragma once

#include "strahler/base/stage_timer.h"
#include "strahler/geometry/polygon.h"
#include "strahler/input/features.h"
#include "strahler/input/params.h"
#include "strahler/network/river_network.h"
#include "strahler/primitives/river_primitive.h"
#include "strahler/primitives/terrain_primitive.h"

#include <cstdint>
#include <string>
#include <vector>

namespace strahler::construction {

/// The primitives one Voronoi block contributes (index ranges, end exclusive).
struct BlockPrimitives {
  std::uint32_t terrainBegin = 0;
  std::uint32_t terrainEnd = 0;
  std::uint32_t riverBegin = 0;
  std::uint32_t riverEnd = 0;

  friend bool operator==(const BlockPrimitives&, const BlockPrimitives&) = default;
};

/// The erosion's residual Δh = eroded − tree on a lattice aligned to the global lattice of its
/// spacing (node (i, j) lies at (i · spacing, j · spacing) in the local frame), stored as whole
/// numbers of kQuantum; zero outside it. Generation computes it (erodeRelief) and evaluation
/// adds its smooth interpolation (World::height).
struct ReliefResidual {
  static constexpr double kQuantum = 0.1; ///< m per stored unit.
  static constexpr int kChunk = 64;       ///< Nodes per side of a stored chunk.
  double spacing = 0.0;                   ///< m between nodes; 0: no residual (no erosion).
  std::int32_t column0 = 0;               ///< Global index of the first column, a kChunk multiple.
  std::int32_t row0 = 0;                  ///< Global index of the first row, a kChunk multiple.
  std::int32_t columns = 0;               ///< Nodes per row, a kChunk multiple.
  std::int32_t rows = 0;                  ///< Rows, a kChunk multiple.
  std::vector<std::int16_t> quanta;       ///< Δh / kQuantum, row-major, columns × rows.

  /// Whether the world has a residual.
  bool empty() const noexcept { return quanta.empty(); }
  friend bool operator==(const ReliefResidual&, const ReliefResidual&) = default;
};

/// Everything a world file holds: the vector description of a world (river graph and its
/// hydrology, terrain and river primitives grouped by block, land outline), plus what made
/// it. Values are already quantised to the file's precision, so a world survives a save and
/// load bit for bit.
struct WorldData {
  std::string name;                ///< Human name of the world ("default", file stem, ...).
  std::string cacheKey;            ///< Hex hash of the canonical spec and generator version.
  std::string generatorVersion;    ///< kGeneratorVersion of the generator that made it.
  input::Params params;            ///< Parameters (seed included) that made it.
  geometry::Vec2 projectionCenter; ///< (lon0, lat0) of the local frame, degrees.
  geometry::MultiPolygon land;     ///< Land in local metres (outer CCW, holes CW).

  network::RiverNetwork network; ///< The river graph (positions, elevations, Strahler).
  std::vector<double> flow;      ///< Per node: φ, m³/s.
  std::vector<primitives::RiverType> riverTypes; ///< Per node: Rosgen type below it.

  std::vector<primitives::TerrainPrimitive> terrain; ///< Grouped by block.
  std::vector<primitives::RiverPrimitive> rivers;    ///< Grouped by block.
  std::vector<BlockPrimitives> blocks;               ///< One per network node.
  /// The artist's vector map the world was made from (its folds are evaluated from the
  /// mountains); empty for most worlds.
  input::Features features;
  /// The erosion's residual over the land (empty: the tree alone, as before generator 8).
  ReliefResidual relief;

  std::vector<base::StageTime> stageSeconds; ///< Generation time per stage (not hashed).

  /// Land area in km².
  double areaKm2() const noexcept;
};

} // namespace strahler::construction
