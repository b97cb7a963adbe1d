// `strahler export-heightmap` run as a user runs it: each engine's size, byte order and
// orientation read back independently of the writer and checked against World::height,
// Unreal's tiles sharing their edges, the same bytes for any thread count, and bad input
// refused with nothing written: exit 2 for a wrong command line, 1 for a wrong file.
#include "engine_heightmap.h"
#include "heightmap_export_support.h"
#include "program_run.h"
#include "serve_process.h"

#include "strahler/construction/world.h"
#include "strahler/image/image.h"
#include "strahler/store/world_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <spng.h>
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

/// Checks that sample (row, column) of the file, read with the sidecar's row order, holds
/// World::height at that point (at the export's spacing) within one quantisation step.
void expectSampleMatchesWorld(const strahler::construction::World& world,
                              const nlohmann::json& side, const std::vector<std::uint16_t>& v,
                              int row, int column) {
  const int n = side["width"];
  const double x0 = side["localBounds"]["x0"], x1 = side["localBounds"]["x1"];
  const double y0 = side["localBounds"]["y0"], y1 = side["localBounds"]["y1"];
  const double lo = side["minHeight"], hi = side["maxHeight"];
  const double dx = (x1 - x0) / (n - 1), dy = (y1 - y0) / (n - 1);
  const bool southFirst = side["row0"] == "south";
  // row counts from the north here; the file's row from its own first row.
  const int fileRow = southFirst ? n - 1 - row : row;
  const double stored =
      lo + v[static_cast<std::size_t>(fileRow) * n + column] / 65535.0 * (hi - lo);
  const double expected = world.height({x0 + column * dx, y1 - row * dy}, std::min(dx, dy));
  EXPECT_NEAR(stored, expected, (hi - lo) / 65535.0 + 0.01)
      << "row " << row << " (from the north), column " << column;
}

/// The row (from the north) and column of the highest sample.
std::pair<int, int> highest(const nlohmann::json& side, const std::vector<std::uint16_t>& v) {
  const int n = side["width"];
  const auto top = static_cast<int>(std::max_element(v.begin(), v.end()) - v.begin());
  const int fileRow = top / n;
  return {side["row0"] == "south" ? n - 1 - fileRow : fileRow, top % n};
}

void expectOrientation(const nlohmann::json& side, const std::vector<std::uint16_t>& v) {
  const int n = side["width"];
  const auto [row, column] = highest(side, v);
  expectSampleMatchesWorld(loadedWorld(), side, v, row, column);
  for (const int r : {0, n / 3, n - 1})
    for (const int c : {0, n / 2, n - 1})
      expectSampleMatchesWorld(loadedWorld(), side, v, r, c);
}

TEST(ExportHeightmap, UnityWritesLittleEndianRawSouthRowFirst) {
  const fs::path dir = outputDir("unity");
  const ProcessRun run = runStrahler("export-heightmap " + islandWorld().string() +
                                     " --engine unity --size 129 -o " + (dir / "h.raw").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(fs::file_size(dir / "h.raw"), 129u * 129u * 2u);
  const nlohmann::json side = readSidecar(dir / "h.json");
  EXPECT_EQ(side["row0"], "south");
  EXPECT_EQ(side["unity"]["resolution"], 129);
  EXPECT_EQ(side["unity"]["byteOrder"], "Windows");
  const std::vector<std::uint16_t> v = readR16(dir / "h.raw");
  EXPECT_EQ(*std::max_element(v.begin(), v.end()), 65535);
  EXPECT_EQ(*std::min_element(v.begin(), v.end()), 0);
  expectOrientation(side, v);
  const double range = side["maxHeight"].get<double>() - side["minHeight"].get<double>();
  EXPECT_DOUBLE_EQ(side["unity"]["terrainSize"]["y"].get<double>(), range);
}

TEST(ExportHeightmap, UnrealWritesPng16NorthRowFirstWithItsZScale) {
  const fs::path dir = outputDir("unreal");
  const ProcessRun run = runStrahler("export-heightmap " + islandWorld().string() +
                                     " --engine unreal --size 505 -o " + (dir / "h.png").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  int width = 0, height = 0;
  const std::vector<std::uint16_t> v = readPng16(dir / "h.png", width, height);
  EXPECT_EQ(width, 505);
  EXPECT_EQ(height, 505);
  const nlohmann::json side = readSidecar(dir / "h.json");
  EXPECT_EQ(side["row0"], "north");
  expectOrientation(side, v);
  const double range = side["maxHeight"].get<double>() - side["minHeight"].get<double>();
  EXPECT_NEAR(side["unreal"]["scaleZ"].get<double>(), range * 100 * 0.001953125, 1e-9);
  EXPECT_NEAR(side["unreal"]["scaleXcm"].get<double>(),
              side["metresPerPixel"]["x"].get<double>() * 100, 1e-9);
}

TEST(ExportHeightmap, GodotAndRawWriteR16NorthRowFirstInABox) {
  const fs::path dir = outputDir("godot");
  for (const char* engine : {"godot", "raw"}) {
    const fs::path file = dir / (std::string(engine) + ".r16");
    const ProcessRun run =
        runStrahler("export-heightmap " + islandWorld().string() + " --engine " + engine +
                    " --size 100 --local -20000,-10000,10000,8000 -o " + file.string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(fs::file_size(file), 100u * 100u * 2u);
    const nlohmann::json side = readSidecar(dir / (std::string(engine) + ".json"));
    EXPECT_EQ(side["localBounds"]["x0"], -20000.0);
    EXPECT_EQ(side["localBounds"]["y1"], 8000.0);
    expectOrientation(side, readR16(file));
  }
  EXPECT_EQ(readSidecar(dir / "godot.json")["godot"]["r16Size"][0], 100);
}

TEST(ExportHeightmap, GodotExrAndRawTiffHoldMetresNorthRowFirst) {
  const fs::path dir = outputDir("float");
  for (const auto& [engine, ext] : {std::pair{"godot", "exr"}, std::pair{"raw", "tif"}}) {
    const fs::path file = dir / (std::string(engine) + "." + ext);
    const ProcessRun run =
        runStrahler("export-heightmap " + islandWorld().string() + " --engine " + engine +
                    " --format " + ext + " --size 97 --quiet -o " + file.string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    // Read back through OpenImageIO (the image module), not the writer's code.
    const auto image = strahler::image::readFloatRaster(file.string());
    ASSERT_TRUE(image) << image.error().message;
    ASSERT_EQ(image.value().width, 97);
    ASSERT_EQ(image.value().height, 97);
    const nlohmann::json side = readSidecar(dir / (std::string(engine) + ".json"));
    EXPECT_EQ(side["row0"], "north");
    const double x0 = side["localBounds"]["x0"], x1 = side["localBounds"]["x1"];
    const double y0 = side["localBounds"]["y0"], y1 = side["localBounds"]["y1"];
    const double dx = (x1 - x0) / 96, dy = (y1 - y0) / 96;
    const auto& pixels = image.value().pixels;
    const auto top =
        static_cast<int>(std::max_element(pixels.begin(), pixels.end()) - pixels.begin());
    EXPECT_FLOAT_EQ(pixels[static_cast<std::size_t>(top)], side["maxHeight"].get<float>());
    for (const int i : {top, 0, 96, 48 * 97 + 20, 96 * 97})
      EXPECT_NEAR(pixels[static_cast<std::size_t>(i)],
                  loadedWorld().height({x0 + (i % 97) * dx, y1 - (i / 97) * dy}, std::min(dx, dy)),
                  1e-3)
          << engine << " pixel " << i;
  }
  EXPECT_EQ(readSidecar(dir / "godot.json")["godot"]["heightScale"], 1.0);
}

TEST(ExportHeightmap, UnrealTilesShareTheirEdgesAndMatchTheWholeExport) {
  const fs::path dir = outputDir("tiles");
  const std::string common = "export-heightmap " + islandWorld().string() +
                             " --engine unreal --format r16 --size 505 --quiet -o ";
  ASSERT_EQ(runStrahler(common + (dir / "whole.r16").string()).exitCode, 0);
  const ProcessRun run = runStrahler(common + (dir / "t.r16").string() + " --tiles 2x2");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::vector<std::uint16_t> whole = readR16(dir / "whole.r16");
  for (int ty = 0; ty < 2; ++ty)
    for (int tx = 0; tx < 2; ++tx) {
      const fs::path file = dir / ("t_x" + std::to_string(tx) + "_y" + std::to_string(ty) + ".r16");
      ASSERT_TRUE(fs::exists(file)) << file;
      const std::vector<std::uint16_t> tile = readR16(file);
      ASSERT_EQ(tile.size(), 253u * 253u);
      for (int r = 0; r < 253; ++r)
        for (int c = 0; c < 253; ++c)
          ASSERT_EQ(tile[static_cast<std::size_t>(r) * 253 + c],
                    whole[static_cast<std::size_t>(ty * 252 + r) * 505 + tx * 252 + c])
              << file << " row " << r << " column " << c;
    }
  // Neighbours share the samples of their common edge.
  const auto left = readR16(dir / "t_x0_y0.r16"), right = readR16(dir / "t_x1_y0.r16");
  for (int r = 0; r < 253; ++r)
    EXPECT_EQ(left[static_cast<std::size_t>(r) * 253 + 252],
              right[static_cast<std::size_t>(r) * 253]);
  const nlohmann::json side = readSidecar(dir / "t.json");
  EXPECT_EQ(side["width"], 505);
  EXPECT_EQ(side["tiles"]["x"], 2);
  EXPECT_EQ(side["tiles"]["width"], 253);
}

TEST(ExportHeightmap, WritesTheSameBytesForOneAndTwoThreads) {
  const fs::path dir = outputDir("threads");
  std::string bytes[2];
  for (int threads = 1; threads <= 2; ++threads) {
    const fs::path file = dir / ("h" + std::to_string(threads) + ".png");
    const ProcessRun run = runStrahler("export-heightmap " + islandWorld().string() +
                                       " --engine unreal --size 1009 --quiet --threads " +
                                       std::to_string(threads) + " -o " + file.string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    bytes[threads - 1] = readWholeFile(file);
  }
  EXPECT_EQ(bytes[0], bytes[1]);
}

TEST(ExportHeightmap, RefusesBadInputWithAPreciseMessageAndWritesNothing) {
  const fs::path dir = outputDir("refused");
  const std::string world = islandWorld().string();
  const std::string out = " -o " + (dir / "h.raw").string();
  // Exit 2: the command line alone is wrong; exit 1: the box does not fit the world read.
  const struct {
    std::string args;
    int exitCode;
    std::string message;
  } cases[] = {
      {"--engine unity --size 1000", 2, "the nearest valid sizes are 513 or 1025"},
      {"--engine unity --size 5000", 2, "the nearest valid sizes are 4097"},
      {"--engine unreal --size 1000", 2, "the nearest valid sizes are 993 or 1009"},
      {"--engine unity --format png16", 2, "Unity imports 16-bit RAW heightmaps only"},
      {"--engine unity --format exr", 2, "Unity imports 16-bit RAW heightmaps only"},
      {"--engine unreal --format exr", 2, "Unreal imports 16-bit PNG or RAW heightmaps"},
      {"--engine godot --format tif", 2, "Godot cannot load TIFF"},
      {"--engine raw --format jpg", 2, "--format jpg: use r16, png16, exr or tif"},
      {"--engine cryengine", 2, "--engine cryengine: use unity, unreal, godot or raw"},
      {"--engine unity --bbox 10,50,11", 2, "--bbox"},
      {"--engine unity --bbox 100,10,101,11", 1, "does not overlap the world's land"},
      {"--engine raw --local 1e7,1e7,2e7,2e7", 1, "does not overlap the world's land"},
      {"--engine raw --local 5,0,1,1", 2, "expected X0 < X1 and Y0 < Y1"},
      {"--engine unity --tiles 2x2", 2, "tiled heightmaps are Unreal's import"},
      {"--engine unreal --size 505 --tiles 5x5", 2, "do not split evenly"},
      {"--engine unreal --format png16 --size 8129", 2, "give --tiles"},
  };
  for (const auto& c : cases) {
    const ProcessRun run = runStrahler("export-heightmap " + world + " " + c.args + out);
    EXPECT_EQ(run.exitCode, c.exitCode) << c.args << ": " << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << c.args << ": " << run.err;
  }
  EXPECT_TRUE(fs::is_empty(dir));
  // The command line itself, and the world file: each message names what is wrong (the option
  // and the value given, or the file and its fault). A command line wrong in itself is a usage
  // error (exit 2, as for every command, docs/cli.md); a missing or damaged file exits 1.
  const fs::path bad = outputDir("refused-worlds");
  const std::string bytes = readWholeFile(world);
  ASSERT_GT(bytes.size(), 1000u);
  const fs::path truncated = bad / "truncated.world", corrupt = bad / "corrupt.world",
                 aFile = bad / "a-file";
  {
    std::ofstream(truncated, std::ios::binary) << bytes.substr(0, 1000);
    std::string flipped = bytes;
    for (std::size_t i = 200; i < 500; ++i)
      flipped[i] = static_cast<char>(flipped[i] ^ 0x5a);
    std::ofstream(corrupt, std::ios::binary) << flipped;
    std::ofstream(aFile) << "not a folder\n";
  }
  const struct {
    std::string args;
    int exitCode;
    std::string message, value;
  } commandLines[] = {
      {world + " --engine raw --bbox -16,64,-15,65 --local 0,0,10,10" + out, 2, "--bbox",
       "--local"},
      {"--engine raw" + out, 2, "WORLD", ""},
      {world + out, 2, "--engine", ""},
      {world + " --engine raw", 2, "-o", ""},
      {world + " --engine unreal --tiles 2" + out, 2, "--tiles", "2"},
      {world + " --engine unreal --tiles 2x" + out, 2, "--tiles", "2x"},
      {world + " --engine unreal --tiles 0x2" + out, 2, "--tiles", "0x2"},
      {world + " --engine unreal --tiles 65x65" + out, 2, "--tiles", "65x65"},
      {world + " --engine raw --size abc" + out, 2, "--size", "abc"},
      {world + " --engine raw --size 1" + out, 2, "--size", "1"},
      {world + " --engine raw --size 99999" + out, 2, "--size", "99999"},
      {world + " --engine raw --threads x" + out, 2, "--threads", "x"},
      {world + " --engine raw --threads 0" + out, 2, "--threads", "0"},
      {world + " --engine raw --threads 100000" + out, 2, "--threads", "100000"},
      {world + " --engine raw --frobnicate" + out, 2, "--frobnicate", ""},
      {(bad / "missing.world").string() + " --engine raw" + out, 1, "missing.world", ""},
      {truncated.string() + " --engine raw" + out, 1, "truncated.world", "truncated"},
      {corrupt.string() + " --engine raw" + out, 1, "corrupt.world", "checksum"},
      {world + " --engine raw -o " + (aFile / "h.r16").string(), 1, "a-file", "folder"},
  };
  for (const auto& c : commandLines) {
    const ProcessRun run = runStrahler("export-heightmap " + c.args);
    EXPECT_EQ(run.exitCode, c.exitCode) << c.args << ": " << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << c.args << ": " << run.err;
    EXPECT_NE(run.err.find(c.value), std::string::npos) << c.args << ": " << run.err;
  }
  EXPECT_TRUE(fs::is_empty(dir));
  for (const auto& entry : fs::directory_iterator(bad)) // the three files written above only
    EXPECT_TRUE(entry.path() == truncated || entry.path() == corrupt || entry.path() == aFile)
        << entry.path();
  // An output folder that does not exist is a failure (exit 1), found before any work.
  const ProcessRun unwritable = runStrahler("export-heightmap " + world + " --engine unity -o " +
                                            (dir / "missing" / "h.raw").string());
  EXPECT_EQ(unwritable.exitCode, 1) << unwritable.err;
  EXPECT_NE(unwritable.err.find("no folder"), std::string::npos) << unwritable.err;
  EXPECT_TRUE(fs::is_empty(dir));
}

/// Starts a tiled export, sends `signal` (after `wait`, or once the first tile's temporary file
/// exists when `wait` is zero) and checks that the process dies by it leaving no file behind.
void interruptExport(int signal, std::chrono::milliseconds wait) {
  const fs::path dir = outputDir("interrupt-" + std::to_string(signal));
  const fs::path out = dir / "big.png";
  strahler::test_support::ServeProcess run(
      {STRAHLER_EXECUTABLE, "export-heightmap", islandWorld().string(), "--engine", "unreal",
       "--size", "4065", "--tiles", "4x4", "--threads", "1", "--quiet", "-o", out.string()},
      "");
  ASSERT_GT(run.pid(), 0);
  if (wait.count() > 0) {
    std::this_thread::sleep_for(wait);
  } else {
    const fs::path temporary =
        (dir / "big_x0_y0.png").string() + ".tmp." + std::to_string(run.pid());
    ASSERT_TRUE(appearsSoon(temporary)) << "no " << temporary << " within 120 s";
  }
  expectInterruptedLeavingNothing(run, signal, dir);
}

TEST(ExportHeightmap, SigtermWhileEvaluatingLeavesNothing) {
  interruptExport(SIGTERM, 500ms);
}

TEST(ExportHeightmap, SigintWhileWritingTilesLeavesNothing) {
  interruptExport(SIGINT, 0ms);
}

TEST(EngineHeightmap, ValidSizesFollowEachEnginesRule) {
  using strahler::app::Engine;
  EXPECT_EQ(strahler::app::validSizes(Engine::kUnity),
            (std::vector<int>{33, 65, 129, 257, 513, 1025, 2049, 4097}));
  const std::vector<int> unreal = strahler::app::validSizes(Engine::kUnreal);
  for (const int recommended : {505, 1009, 2017, 4033, 8129}) // Epic's recommended sizes
    EXPECT_TRUE(std::binary_search(unreal.begin(), unreal.end(), recommended)) << recommended;
  for (const int size : unreal) { // quads per section × sections × components + 1
    bool derived = false;
    for (const int quads : {7, 15, 31, 63, 127, 255})
      for (int sections = 1; sections <= 2; ++sections)
        derived = derived ||
                  ((size - 1) % (quads * sections) == 0 && (size - 1) / (quads * sections) <= 32);
    EXPECT_TRUE(derived) << size;
  }
  EXPECT_EQ(unreal.front(), 8);
  EXPECT_EQ(unreal.back(), 255 * 2 * 32 + 1);
  EXPECT_TRUE(strahler::app::validSizes(Engine::kGodot).empty());
  EXPECT_TRUE(strahler::app::checkSize(Engine::kGodot, 100));
  EXPECT_FALSE(strahler::app::checkSize(Engine::kRaw, 1));
}

TEST(ExportHeightmap, SidecarsGiveSeaLevelsSixteenBitValueAndTheNorthRowOfEachFile) {
  const fs::path dir = outputDir("sea-level");
  const ProcessRun unity =
      runStrahler("export-heightmap " + islandWorld().string() +
                  " --engine unity --size 129 --splat -o " + (dir / "h.raw").string());
  ASSERT_EQ(unity.exitCode, 0) << unity.err;
  const nlohmann::json side = readSidecar(dir / "h.json");
  ASSERT_TRUE(side["seaLevel"]["value16"].is_number()) << side.dump(2);
  const int sea = side["seaLevel"]["value16"];
  const double lo = side["minHeight"], hi = side["maxHeight"];
  ASSERT_LT(lo, 0.0); // the default land's box reaches into the sea
  // The samples below the value are under the sea and those above it on land: the file, read
  // with the sidecar's own encoding, agrees with the value it gives for 0 m.
  int wet = 0, dry = 0;
  for (const std::uint16_t v : readR16(dir / "h.raw")) {
    const double height = lo + v / 65535.0 * (hi - lo);
    if (v < sea) {
      EXPECT_LE(height, (hi - lo) / 65535.0);
      ++wet;
    } else if (v > sea) {
      EXPECT_GE(height, -(hi - lo) / 65535.0);
      ++dry;
    }
  }
  EXPECT_GT(wet, 100);
  EXPECT_GT(dry, 100);
  EXPECT_NE(side["northRow"]["heightmap"].get<std::string>().find("the last row; row 0 is the "
                                                                  "south edge"),
            std::string::npos);
  EXPECT_NE(side["northRow"]["splatMaps"].get<std::string>().find("row 0, the first row: unlike "
                                                                  "this heightmap"),
            std::string::npos);
  // Unreal: row 0 is north in every file; float files hold metres, so sea level is 0.
  const ProcessRun unreal =
      runStrahler("export-heightmap " + islandWorld().string() + " --engine unreal --size 505 -o " +
                  (dir / "u.png").string());
  ASSERT_EQ(unreal.exitCode, 0) << unreal.err;
  const nlohmann::json unrealSide = readSidecar(dir / "u.json");
  EXPECT_EQ(unrealSide["northRow"]["heightmap"], "row 0, the first row");
  EXPECT_TRUE(unrealSide["seaLevel"]["value16"].is_number());
  const ProcessRun exr =
      runStrahler("export-heightmap " + islandWorld().string() +
                  " --engine raw --format exr --size 65 -o " + (dir / "r.exr").string());
  ASSERT_EQ(exr.exitCode, 0) << exr.err;
  EXPECT_EQ(readSidecar(dir / "r.json")["seaLevel"]["value"], 0.0);
}

TEST(EngineHeightmap, QuantizeMapsTheRangeOntoSixteenBits) {
  EXPECT_EQ(strahler::app::quantize(-10, -10, 90), 0);
  EXPECT_EQ(strahler::app::quantize(90, -10, 90), 65535);
  EXPECT_EQ(strahler::app::quantize(40, -10, 90), 32768);
  EXPECT_EQ(strahler::app::quantize(5, 5, 5), 0); // a flat box
}

} // namespace
