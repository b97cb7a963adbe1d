// The same land gives the same world, byte for byte, whichever way its rings run and wherever
// they start: the real program, generating each spelling into its own cache.
#include "coastline_variants.h"
#include "program_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using strahler::test_support::CoastlineRewrite;
using strahler::test_support::ProcessRun;
using strahler::test_support::readWholeFile;
using strahler::test_support::rewriteCoastline;

fs::path scratchDir() {
  return strahler::test_support::processScratchDir(
      fs::path(STRAHLER_BINARY_DIR) / "cli_test_scratch", "canonical");
}

/// What one spelling of a coastline generated: its summary and its world file's bytes.
struct Generated {
  nlohmann::json summary;
  std::string worldBytes;
};

/// Writes `geojson` as `spelling`/`stem`.geojson (the same file name for every spelling: the
/// world file holds the name) and generates it with seed 42 into a cache of its own.
Generated generate(const std::string& geojson, const std::string& spelling,
                   const std::string& stem) {
  const fs::path folder = scratchDir() / stem / spelling;
  fs::remove_all(folder);
  fs::create_directories(folder);
  const fs::path coast = folder / (stem + ".geojson");
  std::ofstream(coast, std::ios::binary) << geojson;
  const fs::path world = folder / "world.world";
  const ProcessRun run = strahler::test_support::runProgram(
      STRAHLER_EXECUTABLE,
      "generate --quiet --json --seed 42 --coast " + coast.string() + " --cache-dir " +
          (folder / "cache").string() + " -o " + world.string(),
      folder);
  EXPECT_EQ(run.exitCode, 0) << spelling << ": " << run.err;
  if (run.exitCode != 0)
    return {};
  return {nlohmann::json::parse(run.out), readWholeFile(world)};
}

void expectTheSameWorldFromEverySpelling(const std::string& geojson, const std::string& stem) {
  const Generated original = generate(geojson, "as-given", stem);
  ASSERT_FALSE(original.worldBytes.empty()) << stem;
  EXPECT_FALSE(original.summary["fromCache"].get<bool>());
  std::printf("%s: %d mouths, %d blocks, key %s\n", stem.c_str(),
              original.summary["mouths"].get<int>(), original.summary["blocks"].get<int>(),
              original.summary["cacheKey"].get<std::string>().c_str());
  const struct {
    const char* name;
    CoastlineRewrite how;
  } spellings[] = {{"reversed", {true, 0, false}}, {"reversed-and-rotated", {true, 37, false}}};
  for (const auto& spelling : spellings) {
    const Generated other = generate(rewriteCoastline(geojson, spelling.how), spelling.name, stem);
    EXPECT_FALSE(other.summary["fromCache"].get<bool>()) << spelling.name; // really generated
    EXPECT_EQ(other.summary["cacheKey"], original.summary["cacheKey"]) << stem << spelling.name;
    EXPECT_EQ(other.summary["mouths"], original.summary["mouths"]) << stem << spelling.name;
    EXPECT_EQ(other.summary["blocks"], original.summary["blocks"]) << stem << spelling.name;
    EXPECT_TRUE(other.worldBytes == original.worldBytes) << stem << " " << spelling.name;
  }
}

TEST(CanonicalCoastline, MallorcaGivesTheSameWorldBytesWhicheverWayItsRingRuns) {
  expectTheSameWorldFromEverySpelling(
      readWholeFile(fs::path(STRAHLER_TEST_DATA_DIR) / "mallorca.geojson"), "mallorca");
}

TEST(CanonicalCoastline, CorsicaGivesTheSameWorldBytesWhicheverWayItsRingRuns) {
  expectTheSameWorldFromEverySpelling(
      readWholeFile(fs::path(STRAHLER_TEST_DATA_DIR) / "corsica.geojson"), "corsica");
}

TEST(CanonicalCoastline, TheDefaultIslandAndItsLakeGiveTheSameWorldBytesEitherWay) {
  expectTheSameWorldFromEverySpelling(
      readWholeFile(fs::path(STRAHLER_SOURCE_DIR) / "core/input/data/default_island.geojson"),
      "default_island");
}

} // namespace
