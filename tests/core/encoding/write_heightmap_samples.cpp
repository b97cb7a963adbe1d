// Writes PNG heightmap tiles and, beside each, the heights a correct decoder must recover
// (clamped to the format's range) as JSON, for tests/node/check_heightmaps.mjs: an
// independent decoder (pngjs and the published formulas) checks our bytes.
//
// Usage: write_heightmap_samples <output folder>   (the folder is emptied first)

#include "strahler/encoding/heightmap_encoder.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using strahler::encoding::encodeHeightmap;
using strahler::encoding::HeightGrid;
using strahler::encoding::HeightmapFormat;

struct FormatInfo {
  HeightmapFormat format;
  const char* name; ///< As check_heightmaps.mjs knows it.
  double lowest;    ///< Decodable range: heights outside are clamped to it.
  double highest;
};

constexpr FormatInfo kFormats[] = {
    {HeightmapFormat::kTerrainRgb, "terrainrgb", -10000.0, 1667721.5},
    {HeightmapFormat::kTerrarium, "terrarium", -32768.0, 32767.99609375},
    {HeightmapFormat::kPng16, "png16", -1000.0, 5553.5},
};

/// Smooth relief (sums of sines) with a fine, noisy-looking ripple; odd sizes catch
/// row/column mix-ups.
HeightGrid terrain(int width, int height, double base, double relief) {
  HeightGrid grid{width, height, {}};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double smooth =
          std::sin(x * 0.05) * std::cos(y * 0.041) + 0.5 * std::sin((x + y) * 0.13);
      const double ripple = 0.03 * std::sin(x * 2.7 + y * 1.9) * std::sin(y * 3.1 - x * 0.7);
      grid.heights.push_back(static_cast<float>(base + relief * (smooth + ripple)));
    }
  return grid;
}

/// Range edges, clamped values and rounding ties for every format.
HeightGrid extremes() {
  return {8, 3, {-40000.0f, -20000.0f, -10000.0f, -9999.95f, -1000.0f,      -999.95f,
                 -0.05f,    0.0f,      0.05f,     0.25f,     1.0f / 256.0f, 8848.86f,
                 5553.5f,   5553.55f,  32767.99f, 32768.0f,  1e6f,          1667721.5f,
                 2e6f,      -32768.0f, 12.34f,    -12.34f,   0.5f,          -0.5f}};
}

std::string json(const HeightGrid& grid, const FormatInfo& info) {
  std::string out = "{\"format\":\"" + std::string(info.name) +
                    "\",\"width\":" + std::to_string(grid.width) +
                    ",\"height\":" + std::to_string(grid.height) + ",\"heights\":[";
  for (std::size_t i = 0; i < grid.heights.size(); ++i) {
    // The float's exact value, printed as the shortest double that round-trips.
    const double expected =
        std::clamp(static_cast<double>(grid.heights[i]), info.lowest, info.highest);
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, expected).ptr;
    out += (i == 0 ? "" : ",") + std::string(text, end);
  }
  return out + "]}\n";
}

bool writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(out);
}

bool writeSample(const fs::path& dir, const std::string& name, const HeightGrid& grid,
                 const FormatInfo& info) {
  const auto png = encodeHeightmap(grid, info.format);
  if (!png.ok()) {
    std::fprintf(stderr, "%s.%s: %s\n", name.c_str(), info.name, png.error().message.c_str());
    return false;
  }
  const fs::path stem = dir / (name + "." + info.name);
  if (!writeFile(stem.string() + ".png", png.value()) ||
      !writeFile(stem.string() + ".json", json(grid, info))) {
    std::fprintf(stderr, "cannot write %s.*\n", stem.c_str());
    return false;
  }
  return true;
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <output folder>\n", argv[0]);
    return 2;
  }
  const fs::path dir = argv[1];
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir, ec);
  if (ec) {
    std::fprintf(stderr, "cannot create %s: %s\n", dir.c_str(), ec.message().c_str());
    return 1;
  }
  const std::pair<std::string, HeightGrid> samples[] = {
      {"relief_67x45", terrain(67, 45, 1200.0, 900.0)},
      {"coast_256", terrain(256, 256, 50.0, 400.0)},
      {"extremes_8x3", extremes()},
  };
  int written = 0;
  for (const auto& [name, grid] : samples)
    for (const FormatInfo& info : kFormats) {
      if (!writeSample(dir, name, grid, info))
        return 1;
      ++written;
    }
  std::printf("wrote %d heightmap samples to %s\n", written, dir.c_str());
  return 0;
}
