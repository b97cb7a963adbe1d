// `strahler export-heightmap --splat`: Unity's RGBA alphamaps and the other engines' 8-bit
// weight PNGs decoded by libspng (not the writer's code): their sizes, weights summing to 255
// at every pixel, water where World::height puts the sea and none on the highest land, the
// same bytes for any thread count, and the sidecar's list of layers and files.
#include "engine_splat.h"
#include "heightmap_export_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <spng.h>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using strahler::test_support::ProcessRun;
using strahler::test_support::readWholeFile;
using namespace strahler::test_support::heightmap_export;

/// An 8-bit PNG decoded by libspng: `channels` bytes per pixel (1 grey, 4 RGBA); sets the size.
std::vector<std::uint8_t> readPng8(const fs::path& file, int channels, int& width, int& height) {
  const std::string bytes = readWholeFile(file);
  spng_ctx* ctx = spng_ctx_new(0);
  spng_set_png_buffer(ctx, bytes.data(), bytes.size());
  spng_ihdr ihdr{};
  EXPECT_EQ(spng_get_ihdr(ctx, &ihdr), 0) << file;
  EXPECT_EQ(ihdr.bit_depth, 8) << file;
  EXPECT_EQ(ihdr.color_type,
            channels == 4 ? SPNG_COLOR_TYPE_TRUECOLOR_ALPHA : SPNG_COLOR_TYPE_GRAYSCALE)
      << file;
  width = static_cast<int>(ihdr.width), height = static_cast<int>(ihdr.height);
  std::vector<std::uint8_t> out(static_cast<std::size_t>(width) * height * channels);
  EXPECT_EQ(spng_decode_image(ctx, out.data(), out.size(), SPNG_FMT_RAW, 0), 0) << file;
  spng_ctx_free(ctx);
  return out;
}

/// Heights (m) of the north-first sample (row, column) of the export's grid.
double worldHeight(const nlohmann::json& side, int row, int column) {
  const int n = side["width"];
  const double x0 = side["localBounds"]["x0"], x1 = side["localBounds"]["x1"];
  const double y0 = side["localBounds"]["y0"], y1 = side["localBounds"]["y1"];
  const double dx = (x1 - x0) / (n - 1), dy = (y1 - y0) / (n - 1);
  return loadedWorld().height({x0 + column * dx, y1 - row * dy}, std::min(dx, dy));
}

TEST(ExportHeightmapSplat, UnrealWeightMapsSumTo255AndPutWaterOnTheSea) {
  const fs::path dir = outputDir("splat-unreal");
  const ProcessRun run =
      runStrahler("export-heightmap " + islandWorld().string() +
                  " --engine unreal --size 253 --splat --quiet -o " + (dir / "h.png").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json side = readSidecar(dir / "h.json");
  const auto& names = strahler::app::kSplatLayerNames;
  ASSERT_EQ(side["splat"]["layers"].size(), names.size());
  std::vector<std::vector<std::uint8_t>> layers;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string file = std::string("h_splat_") + names[k] + ".png";
    EXPECT_EQ(side["splat"]["layers"][k], names[k]);
    EXPECT_EQ(side["splat"]["files"][k], file);
    int w = 0, h = 0;
    layers.push_back(readPng8(dir / file, 1, w, h));
    ASSERT_EQ(w, 253); // Unreal: one weight per landscape vertex, as the heightmap
    ASSERT_EQ(h, 253);
  }
  int sea = 0, land = 0;
  double highest = -1e9;
  std::size_t top = 0;
  for (std::size_t i = 0; i < 253u * 253u; ++i) {
    int sum = 0;
    for (const auto& layer : layers)
      sum += layer[i];
    ASSERT_EQ(sum, 255) << "pixel " << i;
    const double height = worldHeight(side, static_cast<int>(i / 253), static_cast<int>(i % 253));
    if (height > highest)
      highest = height, top = i;
    if (height < -5.0) { // clearly the sea (World::height is below 0 off the coast)
      EXPECT_EQ(layers[4][i], 255) << "sea pixel " << i << " at " << height << " m";
      ++sea;
    } else if (height > 50.0) {
      land += layers[4][i] == 255 ? 0 : 1;
    }
  }
  EXPECT_GT(sea, 1000);
  EXPECT_GT(land, 1000);
  EXPECT_EQ(layers[4][top], 0) << "water on the highest sample";
  // Every layer shows somewhere.
  for (std::size_t k = 0; k < layers.size(); ++k)
    EXPECT_GT(*std::max_element(layers[k].begin(), layers[k].end()), 128) << names[k];
  EXPECT_EQ(side["splat"]["sediment"].get<std::string>().rfind("proxy", 0), 0u);
}

TEST(ExportHeightmapSplat, UnityAlphamapsArePowerOfTwoRgbaNorthUpAndTheSameForAnyThreads) {
  const fs::path dir = outputDir("splat-unity");
  std::string bytes[2][2];
  for (int threads = 1; threads <= 2; ++threads) {
    const std::string stem = "u" + std::to_string(threads);
    const ProcessRun run =
        runStrahler("export-heightmap " + islandWorld().string() +
                    " --engine unity --size 257 --splat --quiet --threads " +
                    std::to_string(threads) + " -o " + (dir / (stem + ".raw")).string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    for (int m = 0; m < 2; ++m)
      bytes[threads - 1][m] =
          readWholeFile(dir / (stem + "_alphamap" + std::to_string(m) + ".png"));
  }
  EXPECT_EQ(bytes[0][0], bytes[1][0]);
  EXPECT_EQ(bytes[0][1], bytes[1][1]);
  int w = 0, h = 0;
  const std::vector<std::uint8_t> first = readPng8(dir / "u1_alphamap0.png", 4, w, h);
  ASSERT_EQ(w, 256); // Unity's alphamap resolution is a power of two: heightmap 2^n + 1 → 2^n
  ASSERT_EQ(h, 256);
  const std::vector<std::uint8_t> second = readPng8(dir / "u1_alphamap1.png", 4, w, h);
  ASSERT_EQ(w, 256);
  const nlohmann::json side = readSidecar(dir / "u1.json");
  EXPECT_EQ(side["splat"]["width"], 256);
  EXPECT_EQ(side["splat"]["files"][1], "u1_alphamap1.png");
  int sea = 0;
  for (int r = 0; r < 256; ++r)
    for (int c = 0; c < 256; ++c) {
      const std::size_t i = (static_cast<std::size_t>(r) * 256 + c) * 4;
      const int sum = first[i] + first[i + 1] + first[i + 2] + first[i + 3] + second[i];
      ASSERT_EQ(sum, 255) << "texel " << r << ", " << c;
      ASSERT_EQ(second[i + 1] + second[i + 2] + second[i + 3], 0);
      // Texel (r, c) lies between samples r..r+1 (from the north), c..c+1: all four corners
      // deep in the sea means water only, whatever the heightmap's own row order.
      double deepest = -1e9;
      for (const int dr : {0, 1})
        for (const int dc : {0, 1})
          deepest = std::max(deepest, worldHeight(side, r + dr, c + dc));
      if (deepest < -5.0) {
        EXPECT_EQ(second[i], 255) << "sea texel " << r << ", " << c;
        ++sea;
      }
    }
  EXPECT_GT(sea, 1000);
}

TEST(ExportHeightmapSplat, UsesTheErosionsSedimentWithErode) {
  const fs::path dir = outputDir("splat-eroded");
  const ProcessRun run =
      runStrahler("export-heightmap " + islandWorld().string() +
                  " --engine raw --local -1500,-1500,1500,1500 --size 129 --splat --erode "
                  "thermal,hydraulic --iterations 20 --talus 30 --quiet -o " +
                  (dir / "e.r16").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json side = readSidecar(dir / "e.json");
  EXPECT_EQ(side["splat"]["sediment"], "the erosion's sediment S (--erode)");
  int w = 0, h = 0;
  const std::vector<std::uint8_t> sediment = readPng8(dir / "e_splat_Sediment.png", 1, w, h);
  ASSERT_EQ(w, 129);
  EXPECT_GT(std::count_if(sediment.begin(), sediment.end(), [](std::uint8_t v) { return v > 0; }),
            100);
}

TEST(ExportHeightmapSplat, UnrealTilesAreCutFromTheWholeWeightMaps) {
  const fs::path dir = outputDir("splat-tiles");
  const std::string common = "export-heightmap " + islandWorld().string() +
                             " --engine unreal --format r16 --size 253 --splat --quiet -o ";
  ASSERT_EQ(runStrahler(common + (dir / "whole.r16").string()).exitCode, 0);
  const ProcessRun run = runStrahler(common + (dir / "t.r16").string() + " --tiles 2x2");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json side = readSidecar(dir / "t.json");
  EXPECT_EQ(side["splat"]["files"].size(), 5u * 4u);
  for (const char* layer : strahler::app::kSplatLayerNames) {
    int w = 0, h = 0;
    const auto whole = readPng8(dir / (std::string("whole_splat_") + layer + ".png"), 1, w, h);
    for (int ty = 0; ty < 2; ++ty)
      for (int tx = 0; tx < 2; ++tx) {
        const std::string name = std::string("t_splat_") + layer + "_x" + std::to_string(tx) +
                                 "_y" + std::to_string(ty) + ".png";
        const auto tile = readPng8(dir / name, 1, w, h);
        ASSERT_EQ(w, 127) << name;
        ASSERT_EQ(h, 127) << name;
        for (int r = 0; r < 127; ++r)
          for (int c = 0; c < 127; ++c)
            ASSERT_EQ(tile[static_cast<std::size_t>(r) * 127 + c],
                      whole[static_cast<std::size_t>(ty * 126 + r) * 253 + tx * 126 + c])
                << name << " row " << r << " column " << c;
      }
  }
  // The tiled heightmap itself is unchanged by --splat (the whole grid, then cut).
  EXPECT_EQ(readR16(dir / "t_x1_y1.r16").size(), 127u * 127u);
}

TEST(ExportHeightmapSplat, RefusesWhatItCannotWrite) {
  const fs::path dir = outputDir("splat-refused");
  const std::string world = "export-heightmap " + islandWorld().string();
  const ProcessRun big =
      runStrahler(world + " --engine raw --size 4097 --splat -o " + (dir / "h.r16").string());
  EXPECT_EQ(big.exitCode, 2); // the command line alone is wrong
  EXPECT_NE(big.err.find("at most 4096 samples per side"), std::string::npos) << big.err;
  const ProcessRun untiled = runStrahler(
      world + " --engine unreal --format r16 --size 8129 --splat -o " + (dir / "h.r16").string());
  EXPECT_EQ(untiled.exitCode, 2);
  EXPECT_NE(untiled.err.find("or Unreal --tiles"), std::string::npos) << untiled.err;
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(SplatWeights, SumTo255WithTheRemainderToTheLargestFractions) {
  using strahler::app::splatWeights;
  using Scores = strahler::app::SplatScores;
  EXPECT_EQ(splatWeights(Scores{1, 1, 1, 0, 0}), (std::array<std::uint8_t, 5>{85, 85, 85, 0, 0}));
  // 255 / 4 = 63.75 each: three get the floor, the remainder (3) goes to the first three.
  EXPECT_EQ(splatWeights(Scores{1, 1, 1, 1, 0}), (std::array<std::uint8_t, 5>{64, 64, 64, 63, 0}));
  EXPECT_EQ(splatWeights(Scores{0, 0, 0, 0, 1}), (std::array<std::uint8_t, 5>{0, 0, 0, 0, 255}));
  EXPECT_EQ(splatWeights(Scores{0.1f, 0.7f, 0.2f, 0, 0}),
            (std::array<std::uint8_t, 5>{26, 178, 51, 0, 0}));
  for (int i = 0; i < 1000; ++i) {
    const Scores s{float(i % 7), float(i % 3) * 0.3f, float(i % 11) * 0.01f, float(i % 5), 0.001f};
    int sum = 0;
    for (const std::uint8_t w : splatWeights(s))
      sum += w;
    ASSERT_EQ(sum, 255) << i;
  }
  // Scores: water alone on water; steep ground is rock; flat bare ground is ground.
  EXPECT_EQ(strahler::app::splatScores(60, 2, 1, true), (Scores{0, 0, 0, 0, 1}));
  EXPECT_EQ(strahler::app::splatScores(60, 2, 1, false), (Scores{0, 1, 0, 0, 0}));
  EXPECT_EQ(strahler::app::splatScores(0, 0, 0, false), (Scores{1, 0, 0, 0, 0}));
}

} // namespace
