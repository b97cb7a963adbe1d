// `strahler export-heightmap --vegetation csv|json`: the plants inside the box, in each
// engine's units and axes (the same plant at consistent places for Unity and Unreal), standing
// on the exported heightmap read back from its file, a box inside another holding exactly its
// share of the plants, the same bytes for any thread count, and bad input refused.
#include "heightmap_export_support.h"
#include "serve_process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using strahler::test_support::ProcessRun;
using strahler::test_support::readWholeFile;
using namespace strahler::test_support::heightmap_export;
using namespace std::chrono_literals;

/// One plant of a CSV file.
struct Plant {
  std::string species;
  double x = 0, y = 0, z = 0, radius = 0;
};

/// The plants of a --vegetation csv file by id (checking the header and unique ids).
std::map<std::string, Plant> readCsv(const fs::path& file) {
  std::istringstream in(readWholeFile(file));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "id,species,x,y,z,radius,scale,yaw");
  std::map<std::string, Plant> plants;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string id, species, v[6];
    std::getline(fields, id, ',');
    std::getline(fields, species, ',');
    for (std::string& f : v)
      std::getline(fields, f, ',');
    EXPECT_EQ(id.size(), 16u) << line;
    EXPECT_TRUE(plants
                    .emplace(id, Plant{species, std::stod(v[0]), std::stod(v[1]), std::stod(v[2]),
                                       std::stod(v[3])})
                    .second)
        << "duplicate id " << id;
  }
  return plants;
}

/// The r16 heightmap's height at (east, north) metres from its south-west corner, bilinear
/// between the file's samples (read back with the sidecar's row order and range).
double heightmapAt(const std::vector<std::uint16_t>& v, const nlohmann::json& side, double east,
                   double north) {
  const int n = side["width"];
  const double lo = side["minHeight"], hi = side["maxHeight"];
  const double column = east / side["metresPerPixel"]["x"].get<double>();
  const double fromSouth = north / side["metresPerPixel"]["y"].get<double>();
  const int c = std::min(static_cast<int>(column), n - 2);
  const int s = std::min(static_cast<int>(fromSouth), n - 2);
  const auto at = [&](int south, int col) {
    const int row = side["row0"] == "south" ? south : n - 1 - south;
    return lo + v[static_cast<std::size_t>(row) * n + col] / 65535.0 * (hi - lo);
  };
  const double tx = column - c, ty = fromSouth - s;
  return (1 - ty) * ((1 - tx) * at(s, c) + tx * at(s, c + 1)) +
         ty * ((1 - tx) * at(s + 1, c) + tx * at(s + 1, c + 1));
}

const std::string kBox = " --local -400,-400,400,400";

TEST(ExportHeightmapVegetation, UnityPlantsStandOnTheHeightmapInsideTheTerrain) {
  const fs::path dir = outputDir("vegetation-unity");
  const ProcessRun run = runStrahler("export-heightmap " + islandWorld().string() + kBox +
                                     " --engine unity --size 129 --vegetation csv --quiet -o " +
                                     (dir / "u.raw").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json side = readSidecar(dir / "u.json");
  const std::vector<std::uint16_t> heights = readR16(dir / "u.raw");
  const std::map<std::string, Plant> plants = readCsv(dir / "u_vegetation.csv");
  EXPECT_GT(plants.size(), 1000u);
  EXPECT_EQ(side["vegetation"]["count"], plants.size());
  EXPECT_EQ(side["vegetation"]["file"], "u_vegetation.csv");
  const double step = (side["minHeight"].get<double>() - side["maxHeight"].get<double>()) / 65535;
  std::set<std::string> species;
  for (const auto& [id, p] : plants) {
    species.insert(p.species);
    ASSERT_GE(p.x, 0.0) << id;
    ASSERT_LE(p.x, 800.0) << id;
    ASSERT_GE(p.z, 0.0) << id; // z north from the south-west corner
    ASSERT_LE(p.z, 800.0) << id;
    // y up: the ground of the imported heightmap under the plant (quantisation, 3 decimals).
    ASSERT_NEAR(p.y, heightmapAt(heights, side, p.x, p.z), std::abs(step) + 2e-3) << id;
    ASSERT_GT(p.radius, 0.0);
    ASSERT_LE(p.radius, 6.0);
  }
  EXPECT_EQ(species, (std::set<std::string>{"bush", "tree"}));
}

TEST(ExportHeightmapVegetation, UnrealJsonIsTheSamePlantsInCentimetresFromTheNorthWest) {
  const fs::path dir = outputDir("vegetation-unreal");
  const std::string common = "export-heightmap " + islandWorld().string() + kBox + " --quiet";
  ASSERT_EQ(runStrahler(common + " --engine unity --size 129 --vegetation csv -o " +
                        (dir / "u.raw").string())
                .exitCode,
            0);
  const ProcessRun run = runStrahler(common + " --engine unreal --size 127 --vegetation json -o " +
                                     (dir / "e.png").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::map<std::string, Plant> unity = readCsv(dir / "u_vegetation.csv");
  const nlohmann::json unreal = nlohmann::json::parse(readWholeFile(dir / "e_vegetation.json"));
  ASSERT_EQ(unreal["instances"].size(), unity.size());
  EXPECT_EQ(readSidecar(dir / "e.json")["vegetation"]["units"], "centimetres");
  for (const nlohmann::json& plant : unreal["instances"]) {
    const auto found = unity.find(plant["id"].get<std::string>());
    ASSERT_NE(found, unity.end()) << plant;
    const Plant& u = found->second;
    EXPECT_EQ(plant["species"], u.species);
    EXPECT_NEAR(plant["position"][0].get<double>(), u.x * 100, 0.2);         // X east
    EXPECT_NEAR(plant["position"][1].get<double>(), (800 - u.z) * 100, 0.2); // Y south
    EXPECT_NEAR(plant["radius"].get<double>(), u.radius * 100, 0.2);
    // Z: the ground in cm. The two grids differ (127 vs 129 samples over 800 m: cells of 6.35
    // and 6.25 m), so a plant's ground comes from samples up to half a cell apart: on the
    // default island's steepest slopes (~40°) that is up to 2.5 m (1.70 m measured).
    EXPECT_NEAR(plant["position"][2].get<double>(), u.y * 100, 250.0);
  }
}

TEST(ExportHeightmapVegetation, AnInnerBoxHoldsExactlyItsPlantsWithAnyThreadCount) {
  const fs::path dir = outputDir("vegetation-boxes");
  const std::string common =
      "export-heightmap " + islandWorld().string() + " --engine raw --size 65 --quiet";
  std::string bytes[2];
  for (int threads = 1; threads <= 2; ++threads) {
    const fs::path out = dir / ("outer" + std::to_string(threads) + ".r16");
    ASSERT_EQ(runStrahler(common + kBox + " --vegetation csv --threads " + std::to_string(threads) +
                          " -o " + out.string())
                  .exitCode,
              0);
    bytes[threads - 1] =
        readWholeFile(dir / ("outer" + std::to_string(threads) + "_vegetation.csv"));
  }
  EXPECT_EQ(bytes[0], bytes[1]);
  ASSERT_EQ(runStrahler(common + " --local -100,-250,300,150 --vegetation csv -o " +
                        (dir / "inner.r16").string())
                .exitCode,
            0);
  const auto outer = readCsv(dir / "outer1_vegetation.csv");
  const auto inner = readCsv(dir / "inner_vegetation.csv");
  std::size_t inside = 0;
  for (const auto& [id, p] : outer) // raw: the world's local metres
    if (p.x >= -100 && p.x <= 300 && p.y >= -250 && p.y <= 150) {
      ++inside;
      ASSERT_TRUE(inner.count(id)) << id << " at " << p.x << ", " << p.y;
    }
  EXPECT_EQ(inner.size(), inside);
  EXPECT_GT(inside, 100u);
}

TEST(ExportHeightmapVegetation, TiledUnrealExportsWriteTheSamePlants) {
  const fs::path dir = outputDir("vegetation-tiles");
  const std::string common = "export-heightmap " + islandWorld().string() + kBox +
                             " --engine unreal --format r16 --size 127 --vegetation csv --quiet";
  ASSERT_EQ(runStrahler(common + " -o " + (dir / "whole.r16").string()).exitCode, 0);
  const ProcessRun run = runStrahler(common + " --tiles 2x2 -o " + (dir / "t.r16").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(readWholeFile(dir / "t_vegetation.csv"), readWholeFile(dir / "whole_vegetation.csv"));
  EXPECT_TRUE(fs::exists(dir / "t_x1_y1.r16"));
}

TEST(ExportHeightmapVegetation, SigtermWhilePlacingPlantsLeavesNothing) {
  const fs::path dir = outputDir("vegetation-interrupt");
  strahler::test_support::ServeProcess run(
      {STRAHLER_EXECUTABLE, "export-heightmap", islandWorld().string(), "--engine", "unity",
       "--local", "-3000,-3000,3000,3000", "--size", "129", "--splat", "--vegetation", "json",
       "--threads", "1", "--quiet", "-o", (dir / "v.raw").string()},
      "");
  ASSERT_GT(run.pid(), 0);
  const fs::path temporary = dir / ("v_vegetation.json.tmp." + std::to_string(run.pid()));
  ASSERT_TRUE(appearsSoon(temporary)) << "no " << temporary << " within 120 s";
  expectInterruptedLeavingNothing(run, SIGTERM, dir);
}

TEST(ExportHeightmapVegetation, RefusesBadInput) {
  const fs::path dir = outputDir("vegetation-refused");
  const std::string world = "export-heightmap " + islandWorld().string();
  const ProcessRun format =
      runStrahler(world + " --engine raw --vegetation xml -o " + (dir / "h.r16").string());
  EXPECT_EQ(format.exitCode, 2); // a wrong command line
  EXPECT_NE(format.err.find("--vegetation xml: use csv or json"), std::string::npos) << format.err;
  EXPECT_TRUE(fs::is_empty(dir));
}

} // namespace
