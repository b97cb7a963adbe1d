#include "world_summary.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

namespace strahler::app {

WorldSummary summarize(const construction::WorldData& w, std::size_t fileBytes) {
  WorldSummary s;
  s.name = w.name;
  s.cacheKey = w.cacheKey;
  s.generatorVersion = w.generatorVersion;
  s.seed = w.params.seed;
  s.areaKm2 = w.areaKm2();
  s.islands = w.land.size();
  for (const geometry::Polygon& p : w.land)
    s.lakes += p.holes.size();
  s.mouths = w.network.mouths.size();
  s.nodes = w.network.nodes.size();
  s.edges = w.network.edgeCount();
  s.blocks = w.blocks.size();
  s.terrainPrimitives = w.terrain.size();
  s.riverPrimitives = w.rivers.size();
  for (const primitives::RiverPrimitive& r : w.rivers)
    s.riverCurvePoints += r.curve.size();
  s.networkLengthKm = w.network.totalLength() / 1000.0;
  s.strahlerHistogram = network::strahlerHistogram(w.network);
  s.riverTypeCounts.assign(4, 0);
  for (primitives::RiverType t : w.riverTypes)
    ++s.riverTypeCounts[static_cast<std::size_t>(t)];
  for (const network::RiverNode& n : w.network.nodes)
    s.maxRiverElevation = std::max(s.maxRiverElevation, n.elevation);
  for (const primitives::TerrainPrimitive& t : w.terrain)
    s.maxTerrainElevation = std::max(s.maxTerrainElevation, t.elevation);
  for (double f : w.flow)
    s.maxFlow = std::max(s.maxFlow, f);
  s.fileBytes = fileBytes;
  s.stages = w.stageSeconds;
  return s;
}

namespace {
std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}
} // namespace

std::string toText(const WorldSummary& s) {
  std::string out;
  auto line = [&](const std::string& label, const std::string& value) {
    out += "  " + label + std::string(16 - std::min<std::size_t>(label.size(), 15), ' ') + value +
           "\n";
  };
  out += "world \"" + s.name + "\" (seed " + std::to_string(s.seed) + ")\n";
  line("land", format("%.1f km²", s.areaKm2) + " (" + std::to_string(s.islands) + " island(s), " +
                   std::to_string(s.lakes) + " lake(s))");
  line("mouths", std::to_string(s.mouths));
  line("nodes", std::to_string(s.nodes));
  line("edges", std::to_string(s.edges));
  line("blocks", std::to_string(s.blocks));
  line("network", format("%.1f km", s.networkLengthKm) +
                      format(" (%.2f km/km²)", s.networkLengthKm / std::max(s.areaKm2, 1e-9)));
  std::string histogram;
  for (std::size_t k = 1; k < s.strahlerHistogram.size(); ++k)
    histogram +=
        (k > 1 ? "  " : "") + std::to_string(k) + ": " + std::to_string(s.strahlerHistogram[k]);
  line("Strahler", histogram);
  line("Rosgen", "B: " + std::to_string(s.riverTypeCounts[0]) +
                     "  E: " + std::to_string(s.riverTypeCounts[1]) +
                     "  D: " + std::to_string(s.riverTypeCounts[2]) +
                     "  D-delta: " + std::to_string(s.riverTypeCounts[3]));
  line("primitives", std::to_string(s.terrainPrimitives) + " terrain, " +
                         std::to_string(s.riverPrimitives) + " river (" +
                         std::to_string(s.riverCurvePoints) + " curve points)");
  line("highest", format("river %.0f m", s.maxRiverElevation) +
                      format(", terrain base %.0f m", s.maxTerrainElevation));
  line("largest flow", format("%.1f m³/s", s.maxFlow));
  line("world file",
       std::to_string(s.fileBytes) + " bytes" +
           format(" (%.0f bytes/km²)", double(s.fileBytes) / std::max(s.areaKm2, 1e-9)) +
           (s.filePath.empty() ? ""
                               : (s.fromCache ? ", loaded from " : ", cached at ") + s.filePath));
  std::string times;
  double total = 0.0;
  for (const base::StageTime& t : s.stages) {
    times += t.stage + format(" %.3f s, ", t.seconds);
    total += t.seconds;
  }
  line("time", times + format("total %.3f s", total));
  return out;
}

std::string toJson(const WorldSummary& s) {
  nlohmann::json stages = nlohmann::json::object();
  for (const base::StageTime& t : s.stages)
    stages[t.stage] = t.seconds;
  nlohmann::json histogram = nlohmann::json::object();
  for (std::size_t k = 1; k < s.strahlerHistogram.size(); ++k)
    histogram[std::to_string(k)] = s.strahlerHistogram[k];
  nlohmann::json j = {{"name", s.name},
                      {"cacheKey", s.cacheKey},
                      {"generatorVersion", s.generatorVersion},
                      {"seed", s.seed},
                      {"areaKm2", s.areaKm2},
                      {"islands", s.islands},
                      {"lakes", s.lakes},
                      {"mouths", s.mouths},
                      {"nodes", s.nodes},
                      {"edges", s.edges},
                      {"blocks", s.blocks},
                      {"networkLengthKm", s.networkLengthKm},
                      {"strahlerHistogram", histogram},
                      {"rosgen",
                       {{"B", s.riverTypeCounts[0]},
                        {"E", s.riverTypeCounts[1]},
                        {"D", s.riverTypeCounts[2]},
                        {"D-delta", s.riverTypeCounts[3]}}},
                      {"primitives",
                       {{"terrain", s.terrainPrimitives},
                        {"river", s.riverPrimitives},
                        {"riverCurvePoints", s.riverCurvePoints}}},
                      {"maxRiverElevation", s.maxRiverElevation},
                      {"maxTerrainElevation", s.maxTerrainElevation},
                      {"maxFlow", s.maxFlow},
                      {"bytes", s.fileBytes},
                      {"bytesPerKm2", double(s.fileBytes) / std::max(s.areaKm2, 1e-9)},
                      {"fromCache", s.fromCache},
                      {"stageSeconds", stages}};
  if (!s.repairs.empty()) {
    nlohmann::json repairs = nlohmann::json::array();
    for (const repair::Change& change : s.repairs)
      repairs.push_back({{"kind", repair::changeKindName(change.kind)},
                         {"lon", change.lonLat.x},
                         {"lat", change.lonLat.y},
                         {"areaKm2", change.areaKm2},
                         {"description", change.description}});
    j["repairs"] = std::move(repairs);
  }
  return j.dump(2);
}

} // namespace strahler::app
