#include "world_summary.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

namespace strahler::app {

WorldSummary summarize(const input::WorldSpec& spec, const analysis::Hydrology& h,
                       const std::vector<base::StageTime>& stages) {
  WorldSummary s;
  s.name = spec.name;
  s.seed = spec.params.seed;
  s.areaKm2 = spec.areaKm2();
  s.islands = spec.land.size();
  for (const geometry::Polygon& p : spec.land)
    s.lakes += p.holes.size();
  s.mouths = h.network.mouths.size();
  s.nodes = h.network.nodes.size();
  s.edges = h.network.edgeCount();
  s.blocks = h.blocks.blocks.size();
  s.networkLengthKm = h.network.totalLength() / 1000.0;
  s.strahlerHistogram = network::strahlerHistogram(h.network);
  s.rosgenCounts.assign(4, 0);
  for (analysis::RosgenType t : h.analysis.rosgen)
    ++s.rosgenCounts[static_cast<std::size_t>(t)];
  for (const network::RiverNode& n : h.network.nodes)
    s.maxRiverElevation = std::max(s.maxRiverElevation, n.elevation);
  for (double z : h.analysis.ridgeElevation)
    s.maxRidgeElevation = std::max(s.maxRidgeElevation, z);
  for (double f : h.analysis.flow)
    s.maxFlow = std::max(s.maxFlow, f);
  s.stages = stages;
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
  line("Rosgen", "B: " + std::to_string(s.rosgenCounts[0]) +
                     "  E: " + std::to_string(s.rosgenCounts[1]) +
                     "  D: " + std::to_string(s.rosgenCounts[2]) +
                     "  D-delta: " + std::to_string(s.rosgenCounts[3]));
  line("highest",
       format("river %.0f m", s.maxRiverElevation) + format(", ridge %.0f m", s.maxRidgeElevation));
  line("largest flow", format("%.1f m³/s", s.maxFlow));
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
  const nlohmann::json j = {{"name", s.name},
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
                             {{"B", s.rosgenCounts[0]},
                              {"E", s.rosgenCounts[1]},
                              {"D", s.rosgenCounts[2]},
                              {"D-delta", s.rosgenCounts[3]}}},
                            {"maxRiverElevation", s.maxRiverElevation},
                            {"maxRidgeElevation", s.maxRidgeElevation},
                            {"maxFlow", s.maxFlow},
                            {"stageSeconds", stages}};
  return j.dump(2);
}

} // namespace strahler::app
