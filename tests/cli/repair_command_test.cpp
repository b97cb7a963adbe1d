// `--repair` on the real program: Natural Earth's Iceland (which crosses itself once) through
// `generate`, and a bow-tie island through `serve --coast`.
#include "program_run.h"
#include "test_client.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using strahler::http::test::readLine;
using strahler::test_support::ProcessRun;
using strahler::test_support::runProgram;

fs::path scratchDir() {
  return strahler::test_support::processScratchDir(
      fs::path(STRAHLER_BINARY_DIR) / "cli_test_scratch", "repair");
}

/// Runs strahler with `args`, a cache in the build tree, and collects its output.
ProcessRun strahler(const std::string& args) {
  return runProgram(STRAHLER_EXECUTABLE, args, scratchDir());
}

const std::string kIceland = std::string(STRAHLER_TEST_DATA_DIR) + "/iceland.geojson";

TEST(RepairCommand, GenerateRefusesIcelandWithoutRepairAndBuildsItWithRepair) {
  const ProcessRun refused = strahler("generate --quiet --coast " + kIceland);
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_NE(refused.err.find("iceland.geojson: coastline: feature 0, polygon 0, ring 0: ring "
                             "intersects itself: segment 511 (positions 511-512) touches or "
                             "crosses segment 513 (positions 513-514) at (-16.48276, 63.90223); "
                             "run with --repair to mend it"),
            std::string::npos)
      << refused.err;

  // The whole island, about 100,000 km² (12 s of generation in a release build).
  fs::remove_all(scratchDir() / "cache");
  const ProcessRun run = strahler("generate --quiet --json --repair --coast " + kIceland);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.err.find("strahler: repaired: self-intersection at (-16.48276, 63.90223), "),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("segments at positions 511-512 and positions 513-514 cross"),
            std::string::npos)
      << run.err;
  const auto summary = nlohmann::json::parse(run.out);
  EXPECT_NEAR(summary["areaKm2"].get<double>(), 101'000.0, 1'500.0);
  EXPECT_LT(summary["bytesPerKm2"].get<double>(), 500.0);
  ASSERT_TRUE(summary.contains("repairs"));
  ASSERT_EQ(summary["repairs"].size(), 3u) << summary["repairs"].dump();
  EXPECT_EQ(summary["repairs"][0]["kind"], "orientation");
  EXPECT_EQ(summary["repairs"][1]["kind"], "self-intersection");
  EXPECT_NEAR(summary["repairs"][1]["lon"].get<double>(), -16.48276, 1e-5);
  EXPECT_LT(summary["repairs"][1]["areaKm2"].get<double>(), 0.1);
  EXPECT_EQ(summary["repairs"][2]["kind"], "pinch");

  // Repaired again, the same land: the world comes from the cache, and the report again.
  const ProcessRun again = strahler("generate --quiet --json --repair --coast " + kIceland);
  ASSERT_EQ(again.exitCode, 0) << again.err;
  const auto cached = nlohmann::json::parse(again.out);
  EXPECT_TRUE(cached["fromCache"].get<bool>());
  EXPECT_EQ(cached["cacheKey"], summary["cacheKey"]);
  EXPECT_EQ(cached["repairs"], summary["repairs"]);
}

TEST(RepairCommand, ServeCoastTakesRepair) {
  // Two triangles of about 24 km² each, drawn as one ring that crosses itself at
  // (3.05, 39.55).
  const fs::path coast = scratchDir() / "bowtie.geojson";
  std::ofstream(coast) << R"({"type":"Polygon","coordinates":[[[3.0,39.5],[3.1,39.6],)"
                          R"([3.1,39.5],[3.0,39.6],[3.0,39.5]]]})";
  const ProcessRun refused =
      strahler("serve --quiet --port 0 --threads 1 --workers 1 --coast " + coast.string());
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_NE(refused.err.find("ring intersects itself"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("run with --repair to mend it"), std::string::npos) << refused.err;

  const std::string command = "echo $$; STRAHLER_CACHE_DIR=" + (scratchDir() / "cache").string() +
                              " exec " + std::string(STRAHLER_EXECUTABLE) +
                              " serve --quiet --port 0 --threads 1 --workers 1 --repair --coast " +
                              coast.string() + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  const pid_t pid = static_cast<pid_t>(std::stol(readLine(pipe)));
  std::string banner, line;
  while ((line = readLine(pipe)).find("serving") == std::string::npos && !std::feof(pipe))
    banner += line + "\n";
  EXPECT_NE(banner.find("strahler: repaired: self-intersection at (3.05000, 39.55000)"),
            std::string::npos)
      << banner;
  EXPECT_NE(banner.find("strahler: repaired: pinch at (3.05000, 39.55000)"), std::string::npos)
      << banner;
  const std::size_t colon = line.rfind(':');
  ASSERT_NE(colon, std::string::npos) << banner << line;
  const auto port = static_cast<std::uint16_t>(std::stoi(line.substr(colon + 1)));
  const auto world =
      strahler::http::test::fetch(port, strahler::http::test::getRequest("/worlds/bowtie"));
  ASSERT_TRUE(world.has_value());
  EXPECT_EQ(world->status, 200) << world->body;
  const auto info = nlohmann::json::parse(world->body, nullptr, false);
  ASSERT_TRUE(info.is_object()) << world->body;
  EXPECT_NEAR(info["areaKm2"].get<double>(), 47.7, 1.0) << world->body;
  ::kill(pid, SIGTERM);
  for (std::string rest; !(rest = readLine(pipe)).empty() || !std::feof(pipe);) {
  }
  pclose(pipe);
}

} // namespace
