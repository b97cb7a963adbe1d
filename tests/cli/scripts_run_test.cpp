// scripts/run pictures the world it serves: the arguments that choose the world (--coast,
// --seed, --params) go to generate and render as well as to serve. Run without installing,
// building or serving (STRAHLER_RUN_PICTURES_ONLY), on a tiny coast.
#include "program_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using strahler::test_support::ProcessRun;
using strahler::test_support::readWholeFile;
using strahler::test_support::runProgram;

fs::path scratchDir() {
  return strahler::test_support::processScratchDir(
      fs::path(STRAHLER_BINARY_DIR) / "cli_test_scratch", "scripts-run");
}

/// An island of about 90 km² off the default island's longitudes, so that its world cannot be
/// mistaken for the default one.
constexpr const char* kTinyCoast =
    R"({"type":"Polygon","coordinates":[[[10.0,45.0],[10.15,45.01],[10.17,45.05],)"
    R"([10.1,45.07],[10.02,45.06],[10.0,45.0]]]})";

TEST(ScriptsRun, PicturesTheCoastSeedAndParamsItServes) {
  const fs::path dir = scratchDir();
  fs::remove_all(dir / "out");
  const fs::path coast = dir / "tiny.geojson";
  std::ofstream(coast) << kTinyCoast;
  const fs::path params = dir / "params.json";
  std::ofstream(params) << R"({"mouthSpacing": 2500})";
  const std::string env =
      "STRAHLER_RUN_PICTURES_ONLY=1 STRAHLER_BIN=" + std::string(STRAHLER_EXECUTABLE) +
      " STRAHLER_RUN_OUT=" + (dir / "out").string() +
      " STRAHLER_RUN_CACHE=" + (dir / "cache").string() + " PORT=0 ";
  const ProcessRun run =
      runProgram(env + std::string(STRAHLER_SOURCE_DIR) + "/scripts/run",
                 "--coast " + coast.string() + " --seed 7 --params=" + params.string() +
                     " --quiet --threads 1",
                 dir);
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  // The world file and both pictures are of the tiny coast with seed 7, not the default island.
  const ProcessRun info =
      runProgram(STRAHLER_EXECUTABLE, "info " + (dir / "out/world.world").string(), dir);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  const auto summary = nlohmann::json::parse(info.out);
  EXPECT_EQ(summary["seed"], 7);
  EXPECT_NEAR(summary["areaKm2"].get<double>(), 90.0, 30.0);
  EXPECT_EQ(summary["name"], "tiny");
  // ... and with the params: the same bytes as generate given all three, not as without params.
  const auto generated = [&](const std::string& extra, const std::string& name) {
    const fs::path world = dir / name;
    const ProcessRun g =
        runProgram(STRAHLER_EXECUTABLE,
                   "generate --quiet --seed 7 --coast " + coast.string() + " --cache-dir " +
                       (dir / "cache").string() + extra + " -o " + world.string(),
                   dir);
    EXPECT_EQ(g.exitCode, 0) << g.err;
    return readWholeFile(world);
  };
  const std::string served = readWholeFile(dir / "out/world.world");
  EXPECT_EQ(served, generated(" --params " + params.string(), "with-params.world"));
  EXPECT_NE(served, generated("", "without-params.world"));
  for (const char* picture : {"out/network.png", "out/relief.png"})
    EXPECT_EQ(readWholeFile(dir / picture).substr(1, 3), "PNG") << picture;
  // serve gets every argument, those of the world included.
  EXPECT_NE(run.out.find("serve --cache-dir " + (dir / "cache").string() + " --port 0 --coast " +
                         coast.string() + " --seed 7 --params=" + params.string() +
                         " --quiet --threads 1"),
            std::string::npos)
      << run.out;
}

} // namespace
