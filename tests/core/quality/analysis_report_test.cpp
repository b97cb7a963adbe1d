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
  return stats;
}

RiverProfileReport sampleRivers() {
  return {500, 1, 1.25, {12.5, -40.0}};
}

TEST(AnalysisReport, ParsesBackWithEveryDocumentedKey) {
  const auto json =
      nlohmann::json::parse(analysisReportJson(sampleDrainage(), sampleHorton(), sampleRivers()));
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

  const auto& rivers = json.at("rivers");
  EXPECT_EQ(rivers.at("samples"), 500);
  EXPECT_EQ(rivers.at("violations"), 1);
  EXPECT_DOUBLE_EQ(rivers.at("worstRiseM").get<double>(), 1.25);
  EXPECT_EQ(rivers.at("worstAt"), (nlohmann::json{12.5, -40.0}));
}

TEST(AnalysisReport, NotANumberBecomesNull) {
  HortonStatistics chain;
  chain.streamCount = {0, 1};
  chain.meanStreamLength = {0.0, 300.0};
  chain.bifurcationRatio = kNaN;
  chain.lengthRatio = kNaN;
  const auto json =
      nlohmann::json::parse(analysisReportJson(sampleDrainage(), chain, sampleRivers()));
  EXPECT_TRUE(json.at("horton").at("bifurcationRatio").is_null());
  EXPECT_TRUE(json.at("horton").at("lengthRatio").is_null());
}

TEST(AnalysisReport, OrdersAndSectionsKeepTheirOrder) {
  HortonStatistics stats;
  stats.streamCount.assign(12, 1);
  stats.meanStreamLength.assign(12, 1.0);
  const std::string text = analysisReportJson(sampleDrainage(), stats, sampleRivers());
  EXPECT_LT(text.find("\"drainage\""), text.find("\"horton\""));
  EXPECT_LT(text.find("\"horton\""), text.find("\"rivers\""));
  EXPECT_LT(text.find("\"9\""), text.find("\"10\"")) << "numeric, not lexicographic, order";
  EXPECT_EQ(text, analysisReportJson(sampleDrainage(), stats, sampleRivers()));
}

} // namespace
} // namespace strahler::quality
