#pragma once

#include "strahler/analysis/hydrology.h"
#include "strahler/base/stage_timer.h"
#include "strahler/input/world_spec.h"

#include <string>
#include <vector>

namespace strahler::app {

/// The figures `strahler generate` reports about a world.
struct WorldSummary {
  std::string name;
  std::uint64_t seed = 0;
  double areaKm2 = 0.0;
  std::size_t islands = 0;
  std::size_t lakes = 0;
  std::size_t mouths = 0;
  std::size_t nodes = 0;
  std::size_t edges = 0;
  std::size_t blocks = 0;
  double networkLengthKm = 0.0;
  std::vector<std::size_t> strahlerHistogram; ///< Index = Strahler number; 0 unused.
  std::vector<std::size_t> rosgenCounts;      ///< Index = RosgenType.
  double maxRiverElevation = 0.0;
  double maxRidgeElevation = 0.0;
  double maxFlow = 0.0;
  std::vector<base::StageTime> stages;
};

/// Collects the summary of a generated world.
WorldSummary summarize(const input::WorldSpec& spec, const analysis::Hydrology& hydrology,
                       const std::vector<base::StageTime>& stages);
/// Human-readable, aligned text.
std::string toText(const WorldSummary& summary);
/// The same as a JSON object.
std::string toJson(const WorldSummary& summary);

} // namespace strahler::app
