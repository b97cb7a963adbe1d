#pragma once

#include "strahler/base/stage_timer.h"
#include "strahler/construction/world_data.h"
#include "strahler/repair/coast_repair.h"

#include <string>
#include <vector>

namespace strahler::app {

/// The figures `strahler generate` and `strahler info` report about a world.
struct WorldSummary {
  std::string name;
  std::string cacheKey;
  std::string generatorVersion;
  std::uint64_t seed = 0;
  double areaKm2 = 0.0;
  std::size_t islands = 0;
  std::size_t lakes = 0;
  std::size_t mouths = 0;
  std::size_t nodes = 0;
  std::size_t edges = 0;
  std::size_t blocks = 0;
  std::size_t terrainPrimitives = 0;
  std::size_t riverPrimitives = 0;
  std::size_t riverCurvePoints = 0;
  double networkLengthKm = 0.0;
  std::vector<std::size_t> strahlerHistogram; ///< Index = Strahler number; 0 unused.
  std::vector<std::size_t> riverTypeCounts;   ///< Index = primitives::RiverType.
  double maxRiverElevation = 0.0;
  double maxTerrainElevation = 0.0; ///< Highest terrain primitive base elevation c_z.
  double maxFlow = 0.0;
  std::size_t fileBytes = 0;
  std::string filePath;
  bool fromCache = false;
  std::vector<base::StageTime> stages;
  std::vector<repair::Change> repairs; ///< What --repair changed; listed in JSON when any.
};

/// Collects the summary of a world whose file has `fileBytes` bytes.
WorldSummary summarize(const construction::WorldData& world, std::size_t fileBytes);
/// Human-readable, aligned text.
std::string toText(const WorldSummary& summary);
/// The same as a JSON object.
std::string toJson(const WorldSummary& summary);

} // namespace strahler::app
