#include "strahler/quality/analysis_report.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace strahler::quality {
namespace {

using Json = nlohmann::ordered_json;

/// A number, or null when it is not finite (JSON has no NaN).
Json number(double value) {
  return std::isfinite(value) ? Json(value) : Json(nullptr);
}

Json drainageJson(const DrainageReport& report) {
  Json json = Json::object();
  json["landCells"] = report.landCells;
  json["drainingCells"] = report.drainingCells;
  json["drainingFraction"] = number(report.drainingFraction);
  json["pits"] = report.pits;
  json["largestUndrainedAreaKm2"] = number(report.largestUndrainedAreaKm2);
  json["fillToleranceM"] = number(report.fillTolerance);
  return json;
}

Json hortonJson(const HortonStatistics& stats) {
  Json counts = Json::object();
  Json lengths = Json::object();
  for (std::size_t k = 1; k < stats.streamCount.size(); ++k) {
    counts[std::to_string(k)] = stats.streamCount[k];
    lengths[std::to_string(k)] =
        k < stats.meanStreamLength.size() ? number(stats.meanStreamLength[k]) : Json(nullptr);
  }
  Json json = Json::object();
  json["streamCount"] = std::move(counts);
  json["meanStreamLengthM"] = std::move(lengths);
  json["bifurcationRatio"] = number(stats.bifurcationRatio);
  json["lengthRatio"] = number(stats.lengthRatio);
  return json;
}

Json riversJson(const RiverProfileReport& report) {
  Json json = Json::object();
  json["samples"] = report.samples;
  json["violations"] = report.violations;
  json["worstRiseM"] = number(report.worstRise);
  json["worstAt"] = Json::array({number(report.worstAt.x), number(report.worstAt.y)});
  return json;
}

} // namespace

std::string analysisReportJson(const DrainageReport& drainage, const HortonStatistics& horton,
                               const RiverProfileReport& rivers) {
  Json json = Json::object();
  json["drainage"] = drainageJson(drainage);
  json["horton"] = hortonJson(horton);
  json["rivers"] = riversJson(rivers);
  return json.dump(2);
}

} // namespace strahler::quality
