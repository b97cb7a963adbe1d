// `strahler export-heightmap --erode` run as a user runs it: the eroded export differs from
// the plain one, conserves material (summed in metres from the file and its sidecar), is the
// seed's erosion (core/erosion) of the plain export's grid with no slope above the talus where
// sediment lies, gives the same bytes for any thread count (tiles cut from the eroded grid),
// and refuses bad parameters leaving nothing behind.
#include "heightmap_export_support.h"
#include "serve_process.h"

#include "strahler/erosion/erosion.h"
#include "strahler/image/image.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <numeric>
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

/// A 3 km square inland, 129 samples per side (23.4 m cells): steep enough for the talus.
const std::string kBox = " --local -1500,-1500,1500,1500 --size 129";
const std::string kErode = " --erode thermal,hydraulic --iterations 20 --talus 30";

/// Heights in metres of an r16 export, from its samples and its sidecar's range.
std::vector<double> metres(const fs::path& r16, const nlohmann::json& side) {
  const double lo = side["minHeight"], hi = side["maxHeight"];
  std::vector<double> out;
  for (const std::uint16_t v : readR16(r16))
    out.push_back(lo + v / 65535.0 * (hi - lo));
  return out;
}

TEST(ExportHeightmapErosion, DiffersFromThePlainExportAndConservesMaterial) {
  const fs::path dir = outputDir("erosion-sums");
  const std::string common = "export-heightmap " + islandWorld().string() + " --engine raw" + kBox;
  ASSERT_EQ(runStrahler(common + " --quiet -o " + (dir / "plain.r16").string()).exitCode, 0);
  const ProcessRun run =
      runStrahler(common + kErode + " --quiet -o " + (dir / "eroded.r16").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json plainSide = readSidecar(dir / "plain.json");
  const nlohmann::json side = readSidecar(dir / "eroded.json");
  const std::vector<double> plain = metres(dir / "plain.r16", plainSide);
  const std::vector<double> eroded = metres(dir / "eroded.r16", side);
  ASSERT_EQ(plain.size(), 129u * 129u);
  ASSERT_EQ(eroded.size(), plain.size());
  int changed = 0;
  double most = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    changed += std::abs(eroded[i] - plain[i]) > 0.5 ? 1 : 0;
    most = std::max(most, std::abs(eroded[i] - plain[i]));
  }
  EXPECT_GT(changed, 500) << "largest change " << most << " m";
  // Material is conserved: the mean heights agree within the two files' quantisation (half a
  // step each) and the float32 grid (1e-4 m).
  const auto step = [](const nlohmann::json& s) {
    return (s["maxHeight"].get<double>() - s["minHeight"].get<double>()) / 65535.0;
  };
  const double n = static_cast<double>(plain.size());
  EXPECT_NEAR(std::accumulate(eroded.begin(), eroded.end(), 0.0) / n,
              std::accumulate(plain.begin(), plain.end(), 0.0) / n,
              (step(plainSide) + step(side)) / 2 + 1e-4);
  // The sidecar records the erosion.
  const nlohmann::json& e = side["erosion"];
  EXPECT_EQ(e["processes"], "thermal,hydraulic");
  EXPECT_EQ(e["iterations"], 20);
  EXPECT_EQ(e["talusDegrees"], 30.0);
  EXPECT_TRUE(e["stable"].get<bool>());
  EXPECT_GT(e["finalSweeps"].get<int>(), 1); // the stabilisation had work to do
  EXPECT_LE(e["talusExcessM"].get<double>(), e["toleranceM"].get<double>());
  EXPECT_NEAR(e["cellMetres"].get<double>(), 3000.0 / 128, 1e-9);
  EXPECT_FALSE(plainSide.contains("erosion"));
}

TEST(ExportHeightmapErosion, IsTheSeedsErosionOfThePlainGridAndKeepsTheTalus) {
  const fs::path dir = outputDir("erosion-talus");
  const std::string common =
      "export-heightmap " + islandWorld().string() + " --engine raw --format exr" + kBox;
  ASSERT_EQ(runStrahler(common + " --quiet -o " + (dir / "plain.exr").string()).exitCode, 0);
  ASSERT_EQ(runStrahler(common + kErode + " --quiet -o " + (dir / "eroded.exr").string()).exitCode,
            0);
  // Both read back through OpenImageIO: float32 metres.
  const auto plain = strahler::image::readFloatRaster((dir / "plain.exr").string());
  const auto eroded = strahler::image::readFloatRaster((dir / "eroded.exr").string());
  ASSERT_TRUE(plain && eroded);
  const std::vector<double> heights(plain.value().pixels.begin(), plain.value().pixels.end());
  strahler::erosion::Params params;
  params.iterations = 20;
  params.talusDegrees = 30;
  params.threads = 1;
  const auto layers = strahler::erosion::erode(heights, 129, 129, 3000.0 / 128, params);
  ASSERT_TRUE(layers) << layers.error().message;
  const std::vector<double> surface = layers.value().surface();
  for (std::size_t i = 0; i < surface.size(); ++i)
    ASSERT_EQ(eroded.value().pixels[i], static_cast<float>(surface[i])) << "sample " << i;
  // After the stabilisation no sediment stands above its neighbours' talus planes.
  EXPECT_TRUE(layers.value().stable);
  EXPECT_LE(strahler::erosion::talusExcess(layers.value(), 30), params.toleranceM);
  double sediment = 0;
  for (const double s : layers.value().sediment)
    sediment += s;
  EXPECT_GT(sediment, 1000.0); // m per cell summed: the erosion did move material
}

TEST(ExportHeightmapErosion, TiledUnrealExportIsCutFromTheErodedGridWithAnyThreadCount) {
  const fs::path dir = outputDir("erosion-tiles");
  const std::string common = "export-heightmap " + islandWorld().string() +
                             " --engine unreal --format r16 --local -2000,-2000,2000,2000 "
                             "--size 253 --quiet" +
                             kErode;
  ASSERT_EQ(runStrahler(common + " --threads 2 -o " + (dir / "whole.r16").string()).exitCode, 0);
  const std::vector<std::uint16_t> whole = readR16(dir / "whole.r16");
  ASSERT_EQ(whole.size(), 253u * 253u);
  std::string bytes[2][4];
  for (int threads = 1; threads <= 2; ++threads) {
    const std::string stem = "t" + std::to_string(threads);
    const ProcessRun run =
        runStrahler(common + " --tiles 2x2 --threads " + std::to_string(threads) + " -o " +
                    (dir / (stem + ".r16")).string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    for (int t = 0; t < 4; ++t)
      bytes[threads - 1][t] = readWholeFile(
          dir / (stem + "_x" + std::to_string(t % 2) + "_y" + std::to_string(t / 2) + ".r16"));
  }
  for (int t = 0; t < 4; ++t) {
    EXPECT_EQ(bytes[0][t], bytes[1][t]) << "tile " << t;
    const std::vector<std::uint16_t> tile =
        readR16(dir / ("t2_x" + std::to_string(t % 2) + "_y" + std::to_string(t / 2) + ".r16"));
    ASSERT_EQ(tile.size(), 127u * 127u);
    for (int r = 0; r < 127; ++r)
      for (int c = 0; c < 127; ++c)
        ASSERT_EQ(tile[static_cast<std::size_t>(r) * 127 + c],
                  whole[static_cast<std::size_t>((t / 2) * 126 + r) * 253 + (t % 2) * 126 + c])
            << "tile " << t << " row " << r << " column " << c;
  }
  EXPECT_TRUE(readSidecar(dir / "t1.json").contains("erosion"));
}

TEST(ExportHeightmapErosion, DefaultBoxIsTheLandsBoxGrownToASquare) {
  const fs::path dir = outputDir("erosion-default-box");
  const std::string world = "export-heightmap " + islandWorld().string() + " --engine raw";
  ASSERT_EQ(runStrahler(world + " --size 65 --quiet -o " + (dir / "plain.r16").string()).exitCode,
            0);
  const ProcessRun eroded =
      runStrahler(world + " --size 65 --erode thermal --iterations 1 --quiet -o " +
                  (dir / "eroded.r16").string());
  ASSERT_EQ(eroded.exitCode, 0) << eroded.err;
  const nlohmann::json land = readSidecar(dir / "plain.json")["localBounds"];
  const nlohmann::json box = readSidecar(dir / "eroded.json")["localBounds"];
  const double landW = land["x1"].get<double>() - land["x0"].get<double>();
  const double landH = land["y1"].get<double>() - land["y0"].get<double>();
  const double side = std::max(landW, landH);
  EXPECT_NEAR(box["x1"].get<double>() - box["x0"].get<double>(), side, 1e-6);
  EXPECT_NEAR(box["y1"].get<double>() - box["y0"].get<double>(), side, 1e-6);
  // The same centre as the land's box, so the square holds all of it.
  EXPECT_NEAR(box["x0"].get<double>() + box["x1"].get<double>(),
              land["x0"].get<double>() + land["x1"].get<double>(), 1e-6);
  EXPECT_NEAR(box["y0"].get<double>() + box["y1"].get<double>(),
              land["y0"].get<double>() + land["y1"].get<double>(), 1e-6);
}

TEST(ExportHeightmapErosion, RefusesBadParametersWithAPreciseMessageAndWritesNothing) {
  const fs::path dir = outputDir("erosion-refused");
  const std::string out = " -o " + (dir / "h.r16").string();
  // Exit 2: the command line alone is wrong; exit 1: the box, from the world, is not square.
  const struct {
    std::string args;
    std::string message;
    int exitCode = 2;
  } cases[] = {
      {"--erode wind", "--erode wind: unknown process 'wind'"},
      {"--erode thermal,", "unknown process ''"},
      {"--erode thermal --iterations 0", "--iterations 0: give 1 … 10000 rounds"},
      {"--erode thermal --iterations 10001", "--iterations 10001: give 1 … 10000 rounds"},
      {"--erode thermal --iterations -3", "--iterations -3: give 1 … 10000 rounds"},
      {"--erode hydraulic --talus 0", "--talus 0: the talus angle is in degrees, in (0, 90)"},
      {"--erode hydraulic --talus 90", "--talus 90: the talus angle"},
      {"--erode hydraulic --talus steep", "--talus steep: the talus angle"},
      {"--iterations 5", "--iterations needs --erode"},
      {"--talus 30", "--talus needs --erode"},
      {"--size 8193 --erode thermal", "at most 4097 samples per side"},
      {"--local -1000,-1000,3000,1000 --erode thermal",
       "needs square cells, and this box gives 3.91 × 1.95 m; give a square box, e.g. --local "
       "-1000,-2000,3000,2000",
       1},
  };
  for (const auto& c : cases) {
    const ProcessRun run =
        runStrahler("export-heightmap " + islandWorld().string() + " --engine raw " + c.args + out);
    EXPECT_EQ(run.exitCode, c.exitCode) << c.args << ": " << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << c.args << ": " << run.err;
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(ExportHeightmapErosion, SigtermWhileErodingLeavesNothing) {
  const fs::path dir = outputDir("erosion-interrupt");
  strahler::test_support::ServeProcess run(
      {STRAHLER_EXECUTABLE, "export-heightmap", islandWorld().string(), "--engine", "raw",
       "--local", "-3000,-3000,3000,3000", "--size", "513", "--erode", "thermal,hydraulic",
       "--iterations", "10000", "--threads", "1", "--quiet", "-o", (dir / "h.r16").string()},
      "");
  ASSERT_GT(run.pid(), 0);
  std::this_thread::sleep_for(1500ms); // evaluated in well under a second; then eroding
  expectInterruptedLeavingNothing(run, SIGTERM, dir);
}

} // namespace
