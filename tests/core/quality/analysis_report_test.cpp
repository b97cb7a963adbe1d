#include "strahler/quality/analysis_report.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <limits>
#include <string>

namespace strahler::quality {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

DrainageReport sampleDrainage() {
  DrainageReport report;
  report.landCells = 1000;
  report.drainingCells = 995;
  report.drainingFraction = 0.995;
  report.pits = 2;
  report.largestUndrainedAreaKm2 = 0.03;
  report.fillTolerance = 1.0;
  return report;
}

HortonStatistics sampleHorton() {
  HortonStatistics stats;
  stats.streamCount = {0, 9, 3, 1};
  stats.meanStreamLength = {0.0, 100.0, 250.0, 600.0};
  stats.bifurcationRatio = 3.0;
  stats.lengthRatio = 2.449;
  stats.fractalDimension = std::numeric_limits<double>::quiet_NaN();
  return stats;
}

RiverProfileReport sampleRivers() {
  return {500, 1, 1.25, {12.5, -40.0}};
}

ReliefReport sampleRelief() {
  ReliefReport relief;
  relief.width = 98;
  relief.height = 180;
  relief.cellSize = 91.5;
  relief.drainingFractionUnburnt = 0.75;
  ReliefFigures& t = relief.terrain;
  t.landCells = 17640;
  t.slopeArea = {0.34, 0.98, 7};
  t.slopes = {11.0, 17.0, 22.0, 0.0, 17000};
  t.confluences = {40, 2, 0.05};
  t.drainageDensity01 = 1.5;
  t.drainageDensity1 = 0.5;
  t.dissection = 5.75;
  NetworkReliefFigures& n = relief.network;
  n.channelsNearRivers = 0.25;
  n.riversNearChannels = 0.5;
  n.networkConfluences = {100, 30, 0.3};
  n.sinuosityB = 1.0;
  n.sinuosityE = 1.25;
  n.sinuosityD = 1.125;
  return relief; // no D-delta river: NaN
}

TEST(AnalysisReport, ParsesBackWithEveryDocumentedKey) {
  const auto json = nlohmann::json::parse(
      analysisReportJson(sampleDrainage(), sampleHorton(), sampleRivers(), sampleRelief()));
  const auto& drainage = json.at("drainage");
  EXPECT_EQ(drainage.at("landCells"), 1000);
  EXPECT_EQ(drainage.at("drainingCells"), 995);
  EXPECT_DOUBLE_EQ(drainage.at("drainingFraction").get<double>(), 0.995);
  EXPECT_EQ(drainage.at("pits"), 2);
  EXPECT_DOUBLE_EQ(drainage.at("largestUndrainedAreaKm2").get<double>(), 0.03);
  EXPECT_DOUBLE_EQ(drainage.at("fillToleranceM").get<double>(), 1.0);

  const auto& horton = json.at("horton");
  EXPECT_EQ(horton.at("streamCount"), (nlohmann::json{{"1", 9}, {"2", 3}, {"3", 1}}));
  EXPECT_DOUBLE_EQ(horton.at("meanStreamLengthM").at("3").get<double>(), 600.0);
  EXPECT_EQ(horton.at("meanStreamLengthM").size(), 3u);
  EXPECT_DOUBLE_EQ(horton.at("bifurcationRatio").get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(horton.at("lengthRatio").get<double>(), 2.449);
  EXPECT_TRUE(horton.at("fractalDimension").is_null()) << "not set in the sample: NaN";
  const auto& coverage = json.at("coverage");
  EXPECT_TRUE(coverage.at("farthestFromRiverM").is_null()) << "not measured";
  EXPECT_TRUE(coverage.at("farthestAt").is_null());

  const auto& rivers = json.at("rivers");
  EXPECT_EQ(rivers.at("samples"), 500);
  EXPECT_EQ(rivers.at("violations"), 1);
  EXPECT_DOUBLE_EQ(rivers.at("worstRiseM").get<double>(), 1.25);
  EXPECT_EQ(rivers.at("worstAt"), (nlohmann::json{12.5, -40.0}));
  EXPECT_DOUBLE_EQ(drainage.at("drainingFractionUnburnt").get<double>(), 0.75);

  const auto& relief = json.at("relief");
  EXPECT_EQ(
      relief.at("raster"),
      (nlohmann::json{{"width", 98}, {"height", 180}, {"cellSizeM", 91.5}, {"landCells", 17640}}));
  EXPECT_EQ(relief.at("slopeArea"), (nlohmann::json{{"theta", 0.34}, {"r2", 0.98}, {"bins", 7}}));
  EXPECT_EQ(relief.at("slopeDeg"), (nlohmann::json{{"p50", 11.0}, {"p90", 17.0}, {"p99", 22.0}}));
  EXPECT_DOUBLE_EQ(relief.at("steeperThan45Fraction").get<double>(), 0.0);
  EXPECT_EQ(relief.at("confluences"), 40);
  EXPECT_DOUBLE_EQ(relief.at("confluences3PlusFraction").get<double>(), 0.05);
  EXPECT_EQ(relief.at("drainageDensityKmPerKm2"), (nlohmann::json{{"0.1", 1.5}, {"1", 0.5}}));
  EXPECT_DOUBLE_EQ(relief.at("dissection").get<double>(), 5.75);
  EXPECT_DOUBLE_EQ(relief.at("channelsNearRiversFraction").get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(relief.at("riversNearChannelsFraction").get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(relief.at("networkConfluences3PlusFraction").get<double>(), 0.3);
  EXPECT_EQ(relief.at("sinuosity"),
            (nlohmann::json{{"B", 1.0}, {"E", 1.25}, {"D", 1.125}, {"D-delta", nullptr}}));
}

TEST(AnalysisReport, ADemReportHasTheSameReliefKeysAllNullWithoutAWorld) {
  ReliefReport report = sampleRelief();
  report.network = NetworkReliefFigures{};
  const auto json = nlohmann::json::parse(demReportJson("a.asc", report));
  EXPECT_EQ(json.at("dem"), "a.asc");
  const auto world = nlohmann::json::parse(
      analysisReportJson(sampleDrainage(), sampleHorton(), sampleRivers(), sampleRelief()));
  const auto& relief = json.at("relief");
  for (const auto& item : world.at("relief").items())
    EXPECT_TRUE(relief.contains(item.key())) << item.key();
  EXPECT_EQ(relief.size(), world.at("relief").size());
  for (const char* key : {"channelsNearRiversFraction", "riversNearChannelsFraction",
                          "networkConfluences3PlusFraction"})
    EXPECT_TRUE(relief.at(key).is_null()) << key;
  for (const auto& item : relief.at("sinuosity").items())
    EXPECT_TRUE(item.value().is_null()) << item.key();
  EXPECT_DOUBLE_EQ(relief.at("dissection").get<double>(), 5.75);
}

TEST(AnalysisReport, GeomorphonsWindowsAndHack) {
  ReliefReport relief = sampleRelief();
  relief.geomorphons.fill(0.0);
  relief.geomorphons[std::size_t(Geomorphon::kSlope)] = 0.75;
  relief.geomorphons[std::size_t(Geomorphon::kHollow)] = 0.25;
  relief.windowKm = 5.0;
  relief.windows.cells = 167;
  ReliefWindow window;
  window.placement = {300, 220, 1159.0};
  window.spectralSlope = 4.5;
  window.geomorphons = relief.geomorphons;
  relief.windows.list = {window};
  relief.windows.meanGeomorphons = relief.geomorphons;
  relief.windows.medianSpectralSlope = 4.5;
  HackLaw hack;
  hack.nodes = {0.75, 0.5, 0.9, 2000};
  const auto json = nlohmann::json::parse(
      analysisReportJson(sampleDrainage(), sampleHorton(), sampleRivers(), relief, hack));
  const auto& shares = json.at("relief").at("geomorphons").at("shares");
  EXPECT_EQ(shares.size(), kGeomorphonCount);
  EXPECT_EQ(shares.begin().key(), "flat") << "in the classes' order";
  EXPECT_DOUBLE_EQ(shares.at("hollow").get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(json.at("relief").at("geomorphons").at("lookupM").get<double>(), 360.0);
  const auto& windows = json.at("relief").at("windows");
  EXPECT_DOUBLE_EQ(windows.at("sizeKm").get<double>(), 5.0);
  EXPECT_EQ(windows.at("cells"), 167);
  EXPECT_DOUBLE_EQ(windows.at("medianSpectralSlope").get<double>(), 4.5);
  ASSERT_EQ(windows.at("list").size(), 1u);
  EXPECT_EQ(windows.at("list")[0].at("row"), 300);
  EXPECT_EQ(windows.at("list")[0].at("col"), 220);
  EXPECT_DOUBLE_EQ(windows.at("list")[0].at("geomorphons").at("slope").get<double>(), 0.75);
  EXPECT_EQ(
      json.at("hack").at("nodes"),
      (nlohmann::json{{"exponent", 0.75}, {"coefficient", 0.5}, {"r2", 0.9}, {"points", 2000}}));
  EXPECT_TRUE(json.at("hack").at("outlets").at("exponent").is_null());
  EXPECT_EQ(json.at("hack").at("outlets").at("points"), 0);
  // Without measurements the shares are null.
  const auto bare = nlohmann::json::parse(
      analysisReportJson(sampleDrainage(), sampleHorton(), sampleRivers(), sampleRelief()));
  EXPECT_TRUE(bare.at("relief").at("geomorphons").at("shares").at("slope").is_null());
  EXPECT_TRUE(bare.at("relief").at("windows").at("list").empty());
}

TEST(AnalysisReport, NotANumberBecomesNull) {
  HortonStatistics chain;
  chain.streamCount = {0, 1};
  chain.meanStreamLength = {0.0, 300.0};
  chain.bifurcationRatio = kNaN;
  chain.lengthRatio = kNaN;
  const auto json = nlohmann::json::parse(
      analysisReportJson(sampleDrainage(), chain, sampleRivers(), sampleRelief()));
  EXPECT_TRUE(json.at("horton").at("bifurcationRatio").is_null());
  EXPECT_TRUE(json.at("horton").at("lengthRatio").is_null());
}

TEST(AnalysisReport, FractalDimensionAndCoverage) {
  HortonStatistics horton = sampleHorton();
  horton.fractalDimension = 1.25;
  NetworkCoverage coverage;
  coverage.farthestM = 2500.0;
  coverage.farthestAt = {100.0, -200.0};
  coverage.fartherThan3KmFraction = 0.0;
  coverage.cellSize = 100.0;
  const std::string text = analysisReportJson(sampleDrainage(), horton, sampleRivers(),
                                              sampleRelief(), HackLaw{}, coverage);
  const auto json = nlohmann::json::parse(text);
  EXPECT_DOUBLE_EQ(json.at("horton").at("fractalDimension").get<double>(), 1.25);
  const auto& c = json.at("coverage");
  EXPECT_DOUBLE_EQ(c.at("farthestFromRiverM").get<double>(), 2500.0);
  EXPECT_EQ(c.at("farthestAt"), (nlohmann::json{100.0, -200.0}));
  EXPECT_DOUBLE_EQ(c.at("fartherThan3KmFraction").get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(c.at("cellSizeM").get<double>(), 100.0);
  EXPECT_TRUE(c.at("definition").is_string());
  EXPECT_LT(text.find("\"hack\""), text.find("\"coverage\""));
  EXPECT_LT(text.find("\"coverage\""), text.find("\"rivers\""));
}

TEST(AnalysisReport, OrdersAndSectionsKeepTheirOrder) {
  HortonStatistics stats;
  stats.streamCount.assign(12, 1);
  stats.meanStreamLength.assign(12, 1.0);
  const std::string text =
      analysisReportJson(sampleDrainage(), stats, sampleRivers(), sampleRelief());
  EXPECT_LT(text.find("\"drainage\""), text.find("\"horton\""));
  EXPECT_LT(text.find("\"horton\""), text.find("\"rivers\""));
  EXPECT_LT(text.find("\"rivers\""), text.find("\"relief\""));
  EXPECT_LT(text.find("\"9\""), text.find("\"10\"")) << "numeric, not lexicographic, order";
  EXPECT_EQ(text, analysisReportJson(sampleDrainage(), stats, sampleRivers(), sampleRelief()));
}

} // namespace
} // namespace strahler::quality
