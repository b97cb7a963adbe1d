// `strahler analyze --dem FILE`: the relief figures of a real DEM (an ESRI ASCII grid made here,
// and the reference DEM in CI), and the refusals of truncated, garbage, huge, missing or
// unreadable DEMs and of bad command lines.
#include "ci_environment.h"
#include "program_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using strahler::test_support::ProcessRun;
using strahler::test_support::runProgram;

fs::path scratchDir() {
  return strahler::test_support::processScratchDir(
      fs::path(STRAHLER_BINARY_DIR) / "cli_test_scratch", "analyze-dem");
}

ProcessRun strahler(const std::string& args) {
  return runProgram(STRAHLER_EXECUTABLE, args, scratchDir());
}

/// Writes `text` to a file of the scratch folder; its path.
fs::path writeScratch(const std::string& name, const std::string& text) {
  const fs::path path = scratchDir() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(WorldCommands, AnalyzeADemPrintsItsReliefFigures) {
  // 60 x 50 cells of 50 m: a valley side tilted towards x = 0 with a NODATA corner.
  std::ostringstream grid;
  grid << "ncols 60\nnrows 50\nxllcorner 0\nyllcorner 0\ncellsize 50\nNODATA_value -9999\n";
  for (int row = 0; row < 50; ++row) {
    for (int col = 0; col < 60; ++col)
      grid << (row < 3 && col < 3 ? -9999.0 : 100.0 + 5.0 * col + 2.0 * std::abs(row - 25)) << ' ';
    grid << '\n';
  }
  const fs::path dem = writeScratch("valley.asc", grid.str());
  const ProcessRun run = strahler("analyze --dem " + dem.string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_EQ(report["dem"], dem.string());
  const auto& relief = report["relief"];
  EXPECT_EQ(relief["raster"]["width"], 60);
  EXPECT_EQ(relief["raster"]["landCells"], 60 * 50 - 9);
  EXPECT_GT(relief["slopeDeg"]["p50"].get<double>(), 5.0);
  EXPECT_TRUE(relief["channelsNearRiversFraction"].is_null());
  EXPECT_TRUE(relief["sinuosity"]["E"].is_null());
  EXPECT_FALSE(report.contains("drainage"));

  // One 2 km window (40 cells) wholly on land, beside the NODATA corner; 26 × 26 interior cells
  // (7 cells of lookup from each edge), of which the axis row looks up 5 ways and down 3 (a
  // hollow) and the rest is plain slope. blind_set.py gives the same on this grid.
  const ProcessRun windowed =
      strahler("analyze --dem " + dem.string() + " --window-km 2 --windows 2");
  ASSERT_EQ(windowed.exitCode, 0) << windowed.err;
  const auto windows = nlohmann::json::parse(windowed.out)["relief"]["windows"];
  EXPECT_EQ(windows["cells"], 40);
  ASSERT_EQ(windows["list"].size(), 1u);
  EXPECT_EQ(windows["list"][0]["row"], 0);
  EXPECT_EQ(windows["list"][0]["col"], 20);
  EXPECT_NEAR(windows["meanGeomorphons"]["hollow"].get<double>(), 1.0 / 26.0, 1e-12);
  EXPECT_NEAR(windows["meanGeomorphons"]["slope"].get<double>(), 25.0 / 26.0, 1e-12);
  EXPECT_TRUE(relief["windows"]["list"].empty()) << "no 7.5 km window in 3 km";
  const ProcessRun resampled =
      strahler("analyze --dem " + dem.string() + " --window-km 2 --window-cell 100");
  ASSERT_EQ(resampled.exitCode, 0) << resampled.err;
  const auto coarseWindows = nlohmann::json::parse(resampled.out)["relief"]["windows"];
  EXPECT_EQ(coarseWindows["cellSizeM"], 100.0);
  EXPECT_EQ(coarseWindows["cells"], 20);

  const ProcessRun scaled = strahler("analyze --dem=" + dem.string() + " --cell-size 100");
  ASSERT_EQ(scaled.exitCode, 0) << scaled.err;
  EXPECT_EQ(nlohmann::json::parse(scaled.out)["relief"]["raster"]["cellSizeM"], 100.0);
}

TEST(WorldCommands, AnalyzeTheReferenceDem) {
  const fs::path dem =
      fs::path(STRAHLER_SOURCE_DIR) / ".." / "shared" / "reference" / "orkhon-valley-92m.asc";
  if (!fs::exists(dem))
    STRAHLER_SKIP_UNLESS_CI(dem << " is absent");
  const ProcessRun run = strahler("analyze --dem " + dem.string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto relief = nlohmann::json::parse(run.out)["relief"];
  EXPECT_NEAR(relief["slopeArea"]["theta"].get<double>(), 0.34, 0.03);
  EXPECT_NEAR(relief["slopeDeg"]["p50"].get<double>(), 11.1, 0.5);
  EXPECT_NEAR(relief["dissection"].get<double>(), 5.8, 0.4);
}

TEST(WorldCommands, AnalyzeRejectsBadDems) {
  const fs::path truncated = writeScratch(
      "short.asc", "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 10\n1 2 3\n4 5\n");
  const ProcessRun shortRun = strahler("analyze --dem " + truncated.string());
  EXPECT_EQ(shortRun.exitCode, 1);
  EXPECT_NE(shortRun.err.find(truncated.string() + "' line 7: the file ends after 5 values"),
            std::string::npos)
      << shortRun.err;
  EXPECT_TRUE(shortRun.out.empty());

  const fs::path text = writeScratch("garbage.asc", "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\n"
                                                    "cellsize 10\n1 2 3\n4 five 6\n");
  const ProcessRun garbage = strahler("analyze --dem " + text.string());
  EXPECT_EQ(garbage.exitCode, 1);
  EXPECT_NE(garbage.err.find("line 7: value 5 ('five'"), std::string::npos) << garbage.err;

  const fs::path huge = writeScratch("huge.asc", "ncols 100000\nnrows 100000\nxllcorner 0\n"
                                                 "yllcorner 0\ncellsize 10\n1\n");
  const ProcessRun big = strahler("analyze --dem " + huge.string());
  EXPECT_EQ(big.exitCode, 1);
  EXPECT_NE(big.err.find("more than the limit"), std::string::npos) << big.err;

  const ProcessRun missing = strahler("analyze --dem /nonexistent/dem.asc");
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("/nonexistent/dem.asc"), std::string::npos) << missing.err;

  const fs::path png = writeScratch("dem.png", "not really a png");
  const ProcessRun noCell = strahler("analyze --dem " + png.string());
  EXPECT_EQ(noCell.exitCode, 1);
  EXPECT_NE(noCell.err.find("--cell-size"), std::string::npos) << noCell.err;
  EXPECT_EQ(strahler("analyze --dem " + png.string() + " --cell-size 30").exitCode, 1);

  EXPECT_EQ(strahler("analyze --dem " + truncated.string() + " some.world").exitCode, 2);
  EXPECT_EQ(strahler("analyze --dem " + truncated.string() + " --cell-size abc").exitCode, 2);
  EXPECT_EQ(strahler("analyze --dem " + truncated.string() + " --cell-size -5").exitCode, 2);
  EXPECT_EQ(strahler("analyze --dem").exitCode, 2);
  EXPECT_EQ(strahler("analyze --dem " + truncated.string() + " --window-km 0").exitCode, 2);
  EXPECT_EQ(strahler("analyze --dem " + truncated.string() + " --windows 101").exitCode, 2);
}

} // namespace
