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

  std::vector<base::StageTime> stageSeconds; ///< Generation time per stage (not hashed).

  /// Land area in km².
  double areaKm2() const noexcept;
};

} // namespace strahler::construction
