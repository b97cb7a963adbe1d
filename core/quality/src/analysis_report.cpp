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

Json drainageJson(const DrainageReport& report, double drainingFractionUnburnt) {
  Json json = Json::object();
  json["landCells"] = report.landCells;
  json["drainingCells"] = report.drainingCells;
  json["drainingFraction"] = number(report.drainingFraction);
  json["drainingFractionUnburnt"] = number(drainingFractionUnburnt);
  json["pits"] = report.pits;
  json["largestUndrainedAreaKm2"] = number(report.largestUndrainedAreaKm2);
  if (report.largestUndrainedAreaKm2 > 0.0)
    json["largestUndrainedAt"] =
        Json::array({number(report.largestUndrainedAt.x), number(report.largestUndrainedAt.y)});
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
  json["fractalDimension"] = number(stats.fractalDimension);
  return json;
}

Json coverageJson(const NetworkCoverage& coverage) {
  Json json = Json::object();
  json["definition"] = "distance from the land point (a cell centre) farthest from every river "
                       "edge of the graph to the nearest edge";
  json["farthestFromRiverM"] = number(coverage.farthestM);
  json["farthestAt"] =
      std::isfinite(coverage.farthestM)
          ? Json::array({number(coverage.farthestAt.x), number(coverage.farthestAt.y)})
          : Json(nullptr);
  json["fartherThan3KmFraction"] = number(coverage.fartherThan3KmFraction);
  json["cellSizeM"] = number(coverage.cellSize);
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

Json hackFitJson(const HackFit& fit) {
  return {{"exponent", number(fit.exponent)},
          {"coefficient", number(fit.coefficient)},
          {"r2", number(fit.r2)},
          {"points", fit.points}};
}

Json hackJson(const HackLaw& hack) {
  Json json = Json::object();
  json["definition"] = "L = c A^h, least squares of log10 L on log10 A; L: km along the river "
                       "graph from a node to its farthest source; A: km2 of the node's block and "
                       "every block upstream; nodes: every node with L > 0; outlets: the mouths";
  json["nodes"] = hackFitJson(hack.nodes);
  json["outlets"] = hackFitJson(hack.outlets);
  return json;
}

Json sharesJson(const GeomorphonShares& shares) {
  Json json = Json::object();
  for (std::size_t c = 0; c < kGeomorphonCount; ++c)
    json[kGeomorphonNames[c]] = number(shares[c]);
  return json;
}

Json windowsJson(const ReliefReport& relief) {
  Json list = Json::array();
  for (const ReliefWindow& w : relief.windows.list)
    list.push_back({{"row", w.placement.row},
                    {"col", w.placement.col},
                    {"reliefM", number(w.placement.reliefM)},
                    {"spectralSlope", number(w.spectralSlope)},
                    {"geomorphons", sharesJson(w.geomorphons)}});
  Json json = Json::object();
  json["sizeKm"] = number(relief.windowKm);
  json["cellSizeM"] = number(relief.windows.cellSize);
  json["cells"] = relief.windows.cells;
  json["meanGeomorphons"] = sharesJson(relief.windows.meanGeomorphons);
  json["medianSpectralSlope"] = number(relief.windows.medianSpectralSlope);
  json["list"] = std::move(list);
  return json;
}

Json comparisonJson(const std::optional<WindowComparison>& comparison) {
  if (!comparison)
    return nullptr;
  Json json = Json::object();
  json["dem"] = comparison->dem;
  json["demCellSizeM"] = number(comparison->demCellSize);
  json["demWindows"] = comparison->demWindows.list.size();
  json["demMeanGeomorphons"] = sharesJson(comparison->demWindows.meanGeomorphons);
  json["demMedianSpectralSlope"] = number(comparison->demWindows.medianSpectralSlope);
  json["geomorphonDistance"] = number(comparison->geomorphonDistance);
  json["spectralSlopeDifference"] = number(comparison->spectralSlopeDifference);
  return json;
}

Json reliefJson(const ReliefReport& relief) {
  const ReliefFigures& t = relief.terrain;
  const NetworkReliefFigures& n = relief.network;
  Json json = Json::object();
  json["raster"] = {{"width", relief.width},
                    {"height", relief.height},
                    {"cellSizeM", number(relief.cellSize)},
                    {"landCells", t.landCells}};
  json["slopeArea"] = {{"theta", number(t.slopeArea.theta)},
                       {"r2", number(t.slopeArea.r2)},
                       {"bins", t.slopeArea.bins}};
  json["slopeDeg"] = {{"p50", number(t.slopes.p50Deg)},
                      {"p90", number(t.slopes.p90Deg)},
                      {"p99", number(t.slopes.p99Deg)}};
  json["steeperThan45Fraction"] = number(t.slopes.steeperThan45);
  json["confluences"] = t.confluences.confluences;
  json["confluences3PlusFraction"] = number(t.confluences.shareThreeOrMore);
  json["drainageDensityKmPerKm2"] = {{"0.1", number(t.drainageDensity01)},
                                     {"1", number(t.drainageDensity1)}};
  json["dissection"] = number(t.dissection);
  json["highestM"] = number(t.highest);
  json["channelsNearRiversFraction"] = number(n.channelsNearRivers);
  json["riversNearChannelsFraction"] = number(n.riversNearChannels);
  json["networkConfluences3PlusFraction"] = number(n.networkConfluences.shareThreeOrMore);
  json["riverDistanceM"] = {{"p99", number(n.riverDistanceP99M)},
                            {"max", number(n.riverDistanceMaxM)},
                            {"fartherThan3KmFraction", number(n.fartherThanCoverageFraction)},
                            {"farthestAt", Json::array({number(n.farthestFromRivers.x),
                                                        number(n.farthestFromRivers.y)})}};
  json["sinuosity"] = {{"B", number(n.sinuosityB)},
                       {"E", number(n.sinuosityE)},
                       {"D", number(n.sinuosityD)},
                       {"D-delta", number(n.sinuosityDelta)}};
  json["geomorphons"] = {{"lookupM", number(relief.geomorphonParams.lookupM)},
                         {"flatDeg", number(relief.geomorphonParams.flatDeg)},
                         {"shares", sharesJson(relief.geomorphons)}};
  json["windows"] = windowsJson(relief);
  json["comparison"] = comparisonJson(relief.comparison);
  return json;
}

} // namespace

std::string analysisReportJson(const DrainageReport& drainage, const HortonStatistics& horton,
                               const RiverProfileReport& rivers, const ReliefReport& relief,
                               const HackLaw& hack, const NetworkCoverage& coverage) {
  Json json = Json::object();
  json["drainage"] = drainageJson(drainage, relief.drainingFractionUnburnt);
  json["horton"] = hortonJson(horton);
  json["hack"] = hackJson(hack);
  json["coverage"] = coverageJson(coverage);
  json["rivers"] = riversJson(rivers);
  json["relief"] = reliefJson(relief);
  return json.dump(2);
}

std::string demReportJson(const std::string& path, const ReliefReport& relief) {
  Json json = Json::object();
  json["dem"] = path;
  json["relief"] = reliefJson(relief);
  return json.dump(2);
}

} // namespace strahler::quality
