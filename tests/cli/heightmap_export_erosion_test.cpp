// `strahler export-heightmap --erode` run as a user runs it: the eroded export differs from
// the plain one, conserves material (summed in metres from the file and its sidecar), moves
// with --erode hydraulic alone what the seed's formula computed here independently moves,
// weathers in place with --erode thermal alone (only the talus moves material), gives the same
// bytes for any thread count (tiles cut from the eroded grid), and refuses bad parameters
// leaving nothing behind.
#include "heightmap_export_support.h"
#include "serve_process.h"

#include "strahler/image/image.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
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
  EXPECT_GE(e["finalSweeps"].get<int>(), 1); // at least the sweep that found it stable
  EXPECT_LE(e["talusExcessM"].get<double>(), e["toleranceM"].get<double>());
  EXPECT_NEAR(e["cellMetres"].get<double>(), 3000.0 / 128, 1e-9);
  EXPECT_FALSE(plainSide.contains("erosion"));
}

/// The plain export of kBox and the export with `erode` (float32 metres, EXR), read back
/// through OpenImageIO.
struct PlainAndEroded {
  std::vector<double> plain, eroded;
};
PlainAndEroded exportBoth(const std::string& name, const std::string& erode) {
  const fs::path dir = outputDir(name);
  const std::string common =
      "export-heightmap " + islandWorld().string() + " --engine raw --format exr" + kBox;
  PlainAndEroded out;
  const ProcessRun plain = runStrahler(common + " --quiet -o " + (dir / "plain.exr").string());
  const ProcessRun eroded =
      runStrahler(common + erode + " --quiet -o " + (dir / "eroded.exr").string());
  EXPECT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_EQ(eroded.exitCode, 0) << eroded.err;
  const auto a = strahler::image::readFloatRaster((dir / "plain.exr").string());
  const auto b = strahler::image::readFloatRaster((dir / "eroded.exr").string());
  if (a && b) {
    out.plain.assign(a.value().pixels.begin(), a.value().pixels.end());
    out.eroded.assign(b.value().pixels.begin(), b.value().pixels.end());
  }
  return out;
}

/// One round of the seed's hydraulic step (seed 004 §1.3.2, as docs/game-engines.md and
/// erosion.h describe it), written here from that description and not from core/erosion:
/// humidity H by flow accumulation (1 m³ per cell, passed from the highest cell down to the
/// lower neighbours in proportion to drop per metre; H = ln water / ln most), tan β by central
/// differences with the edges repeated, and a load min(T·H·tanβ, half the drop) with T = 2 m
/// carried to the steepest-descent neighbour. Returns the surface after it.
std::vector<double> oneHydraulicRound(const std::vector<double>& h, int n, double spacing) {
  const auto at = [n](int x, int y) { return static_cast<std::size_t>(y) * n + x; };
  const auto inside = [n](int x, int y) { return x >= 0 && y >= 0 && x < n && y < n; };
  std::vector<std::size_t> order(h.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return h[a] > h[b]; });
  std::vector<double> water(h.size(), 1.0);
  for (const std::size_t i : order) {
    const int x = static_cast<int>(i % n), y = static_cast<int>(i / n);
    double total = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if ((dx || dy) && inside(x + dx, y + dy) && h[at(x + dx, y + dy)] < h[i])
          total += (h[i] - h[at(x + dx, y + dy)]) / (spacing * std::hypot(dx, dy));
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if ((dx || dy) && inside(x + dx, y + dy) && h[at(x + dx, y + dy)] < h[i])
          water[at(x + dx, y + dy)] +=
              water[i] * (h[i] - h[at(x + dx, y + dy)]) / (spacing * std::hypot(dx, dy)) / total;
  }
  const double most = *std::max_element(water.begin(), water.end());
  std::vector<double> out = h;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const auto clampedAt = [&](int cx, int cy) {
        return h[at(std::clamp(cx, 0, n - 1), std::clamp(cy, 0, n - 1))];
      };
      const double tanBeta = std::hypot(clampedAt(x + 1, y) - clampedAt(x - 1, y),
                                        clampedAt(x, y + 1) - clampedAt(x, y - 1)) /
                             (2 * spacing);
      double best = 0.0, drop = 0.0;
      std::size_t to = h.size();
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if ((dx || dy) && inside(x + dx, y + dy)) {
            const double d = h[at(x, y)] - h[at(x + dx, y + dy)];
            if (d / (spacing * std::hypot(dx, dy)) > best) {
              best = d / (spacing * std::hypot(dx, dy));
              drop = d;
              to = at(x + dx, y + dy);
            }
          }
      if (to == h.size())
        continue;
      const double humidity = std::log(water[at(x, y)]) / std::log(most);
      const double load = std::min(2.0 * humidity * tanBeta, 0.5 * drop);
      out[at(x, y)] -= load;
      out[to] += load;
    }
  return out;
}

TEST(ExportHeightmapErosion, HydraulicAloneMovesWhatTheSeedsFormulaMoves) {
  // One round, and a talus of 89.9° (1.3 km per 23 m cell) so that the stabilisation moves
  // nothing: the change is the hydraulic step's alone, computed here independently.
  const PlainAndEroded run = exportBoth("erosion-hydraulic", " --erode hydraulic --iterations 1 "
                                                             "--talus 89.9");
  ASSERT_EQ(run.plain.size(), 129u * 129u);
  ASSERT_EQ(run.eroded.size(), run.plain.size());
  const std::vector<double> expected = oneHydraulicRound(run.plain, 129, 3000.0 / 128);
  double moved = 0.0, expectedMoved = 0.0;
  int agree = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    moved += std::abs(run.eroded[i] - run.plain[i]);
    expectedMoved += std::abs(expected[i] - run.plain[i]);
    agree += std::abs(run.eroded[i] - expected[i]) <= 1e-3 ? 1 : 0;
  }
  std::printf("hydraulic alone: %.1f m moved (the formula: %.1f m), %d of %zu cells within 1 mm\n",
              moved, expectedMoved, agree, expected.size());
  EXPECT_GT(expectedMoved, 100.0) << "m summed over the cells: the step has work to do";
  EXPECT_NEAR(moved, expectedMoved, 0.01 * expectedMoved);
  // The file holds float32 heights: a near-tie of two descents may go the other way here.
  EXPECT_GE(agree, static_cast<int>(0.99 * static_cast<double>(expected.size())))
      << "cells within 1 mm of the formula";
}

TEST(ExportHeightmapErosion, ThermalAloneWeathersInPlaceAndOnlyTheTalusMovesIt) {
  // Weathering turns bedrock into sediment where it stands: with a talus nothing exceeds, the
  // surface is the plain export's. With a 30° talus the sediment on steep ground slides down:
  // the surface changes and the material is conserved. (If thermal did nothing, there would
  // be no sediment for the talus to move.)
  const PlainAndEroded still =
      exportBoth("erosion-thermal-still", " --erode thermal --iterations 5 --talus 89.9");
  ASSERT_EQ(still.eroded.size(), 129u * 129u);
  for (std::size_t i = 0; i < still.plain.size(); ++i)
    ASSERT_NEAR(still.eroded[i], still.plain[i], 1e-3) << "sample " << i;
  const PlainAndEroded slid =
      exportBoth("erosion-thermal-talus", " --erode thermal --iterations 20 --talus 30");
  ASSERT_EQ(slid.eroded.size(), 129u * 129u);
  int changed = 0;
  for (std::size_t i = 0; i < slid.plain.size(); ++i)
    changed += std::abs(slid.eroded[i] - slid.plain[i]) > 0.5 ? 1 : 0;
  std::printf("thermal alone, 30° talus: %d cells changed by more than 0.5 m\n", changed);
  EXPECT_GT(changed, 200);
  const double n = static_cast<double>(slid.plain.size());
  EXPECT_NEAR(std::accumulate(slid.eroded.begin(), slid.eroded.end(), 0.0) / n,
              std::accumulate(slid.plain.begin(), slid.plain.end(), 0.0) / n, 1e-3);
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
