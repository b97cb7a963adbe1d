#include "png_encoder.h"
#include "result_matchers.h"

#include "strahler/encoding/heightmap_encoder.h"
#include "strahler/encoding/rgb_png.h"
#include "strahler/image/image.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <spng.h>
#include <string>
#include <utility>
#include <vector>

namespace strahler::encoding {
namespace {

namespace fs = std::filesystem;
using base::ErrorCode;

constexpr std::array kAllFormats = {HeightmapFormat::kTerrainRgb, HeightmapFormat::kTerrarium,
                                    HeightmapFormat::kPng16, HeightmapFormat::kTiff,
                                    HeightmapFormat::kExr};

/// Hills from sums of sines (±1100 m, up to ~50 m per pixel) plus a pixel-scale ripple.
HeightGrid terrain(int width, int height) {
  HeightGrid grid{width, height, {}};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double hills =
          800.0 * std::sin(x * 0.05) * std::cos(y * 0.04) + 300.0 * std::sin((x + y) * 0.13);
      const double ripple = 12.0 * std::sin(x * 2.7 + y * 1.9) * std::sin(y * 3.1 - x * 0.7);
      grid.heights.push_back(static_cast<float>(1500.0 + hills + ripple));
    }
  return grid;
}

/// A gentle slope as a zoomed-in tile shows it: under 1 m per pixel, no pixel noise.
HeightGrid gentleSlope(int width, int height) {
  HeightGrid grid{width, height, {}};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      grid.heights.push_back(static_cast<float>(300.0 + 0.4 * x - 0.25 * y +
                                                6.0 * std::sin(x * 0.03) * std::cos(y * 0.02)));
  return grid;
}

/// A row of heights.
HeightGrid row(std::vector<float> heights) {
  const int width = static_cast<int>(heights.size());
  return {width, 1, std::move(heights)};
}

struct DecodedPng {
  spng_ihdr header{};
  std::vector<std::uint8_t> samples; ///< As stored: 16-bit samples big-endian.
};

/// Decodes with libspng, leaving samples untransformed (SPNG_FMT_RAW).
DecodedPng decodePng(const std::string& bytes) {
  DecodedPng out;
  const std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> ctx(spng_ctx_new(0), spng_ctx_free);
  EXPECT_EQ(spng_set_png_buffer(ctx.get(), bytes.data(), bytes.size()), 0);
  EXPECT_EQ(spng_get_ihdr(ctx.get(), &out.header), 0);
  std::size_t size = 0;
  EXPECT_EQ(spng_decoded_image_size(ctx.get(), SPNG_FMT_RAW, &size), 0);
  out.samples.resize(size);
  EXPECT_EQ(spng_decode_image(ctx.get(), out.samples.data(), size, SPNG_FMT_RAW, 0), 0);
  return out;
}

/// Mapbox Terrain-RGB, as published.
std::vector<double> decodeTerrainRgb(const DecodedPng& png) {
  std::vector<double> heights;
  for (std::size_t i = 0; i + 2 < png.samples.size(); i += 3)
    heights.push_back(-10000.0 +
                      (png.samples[i] * 65536.0 + png.samples[i + 1] * 256.0 + png.samples[i + 2]) *
                          0.1);
  return heights;
}

/// Terrarium, as published.
std::vector<double> decodeTerrarium(const DecodedPng& png) {
  std::vector<double> heights;
  for (std::size_t i = 0; i + 2 < png.samples.size(); i += 3)
    heights.push_back(png.samples[i] * 256.0 + png.samples[i + 1] + png.samples[i + 2] / 256.0 -
                      32768.0);
  return heights;
}

/// png16 as documented in heightmap_encoder.h.
std::vector<double> decodePng16(const DecodedPng& png) {
  std::vector<double> heights;
  for (std::size_t i = 0; i + 1 < png.samples.size(); i += 2)
    heights.push_back((png.samples[i] * 256.0 + png.samples[i + 1]) * 0.1 - 1000.0);
  return heights;
}

std::string encode(const HeightGrid& grid, HeightmapFormat format) {
  auto bytes = encodeHeightmap(grid, format);
  EXPECT_TRUE(bytes.ok()) << (bytes.ok() ? "" : bytes.error().message);
  return bytes.ok() ? std::move(bytes).value() : std::string();
}

std::vector<std::uint8_t> samplesOf(const std::vector<float>& heights, HeightmapFormat format) {
  return decodePng(encode(row(heights), format)).samples;
}

/// Chunk types in file order (after the 8-byte signature).
std::vector<std::string> chunkTypes(const std::string& png) {
  std::vector<std::string> types;
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    const auto byte = [&](std::size_t i) {
      return static_cast<std::uint32_t>(static_cast<std::uint8_t>(png[i]));
    };
    const std::uint32_t length =
        byte(at) << 24 | byte(at + 1) << 16 | byte(at + 2) << 8 | byte(at + 3);
    types.push_back(png.substr(at + 4, 4));
    at += 12 + length;
  }
  return types;
}

// ---------------------------------------------------------------------------------------------
// Terrain-RGB

TEST(TerrainRgb, SeaLevelIsTheMapboxCode) {
  // round((0 + 10000) / 0.1) = 100000 = 0x0186A0.
  EXPECT_EQ(samplesOf({0.0f}, HeightmapFormat::kTerrainRgb),
            (std::vector<std::uint8_t>{1, 134, 160}));
}

TEST(TerrainRgb, RoundsToTheNearestTenthOfAMetre) {
  // 0.04 → 100000.4 → 100000; 0.06 → 100000.6 → 100001; 8848.86 → 188488.6 → 188489 = 0x02E049.
  EXPECT_EQ(samplesOf({0.04f, 0.06f, 8848.86f}, HeightmapFormat::kTerrainRgb),
            (std::vector<std::uint8_t>{1, 134, 160, 1, 134, 161, 2, 224, 73}));
}

TEST(TerrainRgb, DecodesWithinFiveCentimetres) {
  const HeightGrid grid = terrain(67, 45);
  const std::vector<double> decoded =
      decodeTerrainRgb(decodePng(encode(grid, HeightmapFormat::kTerrainRgb)));
  ASSERT_EQ(decoded.size(), grid.heights.size());
  for (std::size_t i = 0; i < decoded.size(); ++i)
    ASSERT_NEAR(decoded[i], grid.heights[i], 0.05 + 1e-9) << "pixel " << i;
}

TEST(TerrainRgb, IsAnEightBitRgbPngWithNoAncillaryChunks) {
  const std::string bytes = encode(terrain(300, 20), HeightmapFormat::kTerrainRgb);
  const DecodedPng png = decodePng(bytes);
  EXPECT_EQ(png.header.width, 300u);
  EXPECT_EQ(png.header.height, 20u);
  EXPECT_EQ(png.header.bit_depth, 8);
  EXPECT_EQ(png.header.color_type, SPNG_COLOR_TYPE_TRUECOLOR);
  EXPECT_EQ(png.header.interlace_method, 0);
  for (const std::string& type : chunkTypes(bytes))
    EXPECT_TRUE(type == "IHDR" || type == "IDAT" || type == "IEND") << type;
  EXPECT_EQ(chunkTypes(bytes).back(), "IEND");
}

TEST(TerrainRgb, ClampsToItsTwentyFourBitRange) {
  const std::vector<double> decoded = decodeTerrainRgb(
      decodePng(encode(row({-20000.0f, 1e6f, 2e6f}), HeightmapFormat::kTerrainRgb)));
  EXPECT_DOUBLE_EQ(decoded[0], -10000.0);
  EXPECT_NEAR(decoded[1], 1e6, 1e-6); // in range: kept
  EXPECT_NEAR(decoded[2], 1667721.5, 1e-6);
}

// ---------------------------------------------------------------------------------------------
// Terrarium

TEST(Terrarium, CodesFollowTheFloorFormula) {
  // 0 → v = 32768 → (128, 0, 0); −0.5 → 32767.5 → (127, 255, 128); 1/256 → (128, 0, 1).
  EXPECT_EQ(samplesOf({0.0f, -0.5f, 1.0f / 256.0f}, HeightmapFormat::kTerrarium),
            (std::vector<std::uint8_t>{128, 0, 0, 127, 255, 128, 128, 0, 1}));
}

TEST(Terrarium, DecodesToLessThanOneStepBelowTheHeight) {
  const HeightGrid grid = terrain(67, 45);
  const std::vector<double> decoded =
      decodeTerrarium(decodePng(encode(grid, HeightmapFormat::kTerrarium)));
  ASSERT_EQ(decoded.size(), grid.heights.size());
  for (std::size_t i = 0; i < decoded.size(); ++i) {
    const double below = grid.heights[i] - decoded[i];
    ASSERT_GE(below, 0.0) << "pixel " << i;
    ASSERT_LT(below, 1.0 / 256.0) << "pixel " << i;
  }
}

TEST(Terrarium, ClampsToItsRange) {
  EXPECT_EQ(samplesOf({-40000.0f, 1e6f, -20000.0f}, HeightmapFormat::kTerrarium),
            (std::vector<std::uint8_t>{0, 0, 0, 255, 255, 255, 49, 224, 0})); // −20000 fits
}

// ---------------------------------------------------------------------------------------------
// 16-bit grey

TEST(Png16, SeaLevelIsTenThousandBigEndian) {
  EXPECT_EQ(samplesOf({0.0f, 0.05f}, HeightmapFormat::kPng16),
            (std::vector<std::uint8_t>{0x27, 0x10, 0x27, 0x11})); // 10000, 10000.5 → 10001
}

TEST(Png16, IsASixteenBitGreyPngDecodingWithinFiveCentimetres) {
  const HeightGrid grid = terrain(45, 67);
  const DecodedPng png = decodePng(encode(grid, HeightmapFormat::kPng16));
  EXPECT_EQ(png.header.bit_depth, 16);
  EXPECT_EQ(png.header.color_type, SPNG_COLOR_TYPE_GRAYSCALE);
  const std::vector<double> decoded = decodePng16(png);
  ASSERT_EQ(decoded.size(), grid.heights.size());
  for (std::size_t i = 0; i < decoded.size(); ++i)
    ASSERT_NEAR(decoded[i], grid.heights[i], 0.05 + 1e-9) << "pixel " << i;
}

TEST(Png16, ClampsToItsRange) {
  const std::vector<double> decoded =
      decodePng16(decodePng(encode(row({-20000.0f, 1e6f}), HeightmapFormat::kPng16)));
  EXPECT_NEAR(decoded[0], -1000.0, 1e-9);
  EXPECT_NEAR(decoded[1], 5553.5, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// PNG settings (png_encoder.h): LZ77 where it pays, run-length coding where it cannot

/// Terrain-RGB samples of a grid, packed as the encoder packs them.
std::vector<std::uint8_t> terrainRgbSamples(const HeightGrid& grid) {
  return decodePng(encode(grid, HeightmapFormat::kTerrainRgb)).samples;
}

TEST(PngSettings, SmoothTerrainUsesLz77AndRoughTerrainRunLengths) {
  const HeightGrid smooth = gentleSlope(256, 256);
  const HeightGrid rough = terrain(256, 256);
  EXPECT_GT(detail::predictableShare(terrainRgbSamples(smooth), 256, 256, detail::PngLayout::kRgb8),
            0.3);
  EXPECT_LT(detail::predictableShare(terrainRgbSamples(rough), 256, 256, detail::PngLayout::kRgb8),
            0.3);
  EXPECT_EQ(detail::choosePngOptions(terrainRgbSamples(smooth), 256, 256, detail::PngLayout::kRgb8)
                .strategy,
            detail::ZlibStrategy::kDefault);
  EXPECT_EQ(detail::choosePngOptions(terrainRgbSamples(rough), 256, 256, detail::PngLayout::kRgb8)
                .strategy,
            detail::ZlibStrategy::kRle);
}

TEST(PngSettings, PredictableShareCountsRepeatedSteps) {
  // Grey 16-bit, one row: steps +1, +1, +1 (two repeats), then +5 and +5 again (one repeat).
  const std::vector<std::uint8_t> ramp = {0, 10, 0, 11, 0, 12, 0, 13, 0, 18, 0, 23};
  EXPECT_DOUBLE_EQ(detail::predictableShare(ramp, 6, 1, detail::PngLayout::kGray16), 3.0 / 4.0);
  EXPECT_DOUBLE_EQ(detail::predictableShare({1, 2, 3, 4}, 2, 1, detail::PngLayout::kGray16), 0.0);
}

TEST(PngSettings, EverySettingDecodesToTheSameSamples) {
  const std::vector<std::uint8_t> samples = terrainRgbSamples(terrain(40, 30));
  for (int filter = 0; filter <= 5; ++filter)
    for (int strategy = 0; strategy <= 3; ++strategy) {
      const detail::PngOptions options{1 + filter % 3, static_cast<detail::PngFilter>(filter),
                                       static_cast<detail::ZlibStrategy>(strategy)};
      STRAHLER_ASSIGN_OR_ASSERT(
          const auto png, detail::encodePng(samples, 40, 30, detail::PngLayout::kRgb8, options));
      EXPECT_EQ(decodePng(png).samples, samples) << filter << " " << strategy;
    }
}

// ---------------------------------------------------------------------------------------------
// float TIFF and EXR

void expectFloatRoundTrip(HeightmapFormat format, image::FloatImageFormat container) {
  HeightGrid grid = terrain(67, 45);
  grid.heights[0] = -20000.0f;
  grid.heights[1] = 1e6f;
  grid.heights[2] = std::numeric_limits<float>::denorm_min();
  grid.heights[3] = -0.0f;
  const auto decoded = image::decodeFloatImage(encode(grid, format), container);
  ASSERT_TRUE(decoded.ok()) << decoded.error().message;
  EXPECT_EQ(decoded.value().width, 67);
  EXPECT_EQ(decoded.value().height, 45);
  ASSERT_EQ(decoded.value().pixels.size(), grid.heights.size());
  for (std::size_t i = 0; i < grid.heights.size(); ++i)
    ASSERT_EQ(std::bit_cast<std::uint32_t>(decoded.value().pixels[i]),
              std::bit_cast<std::uint32_t>(grid.heights[i]))
        << "pixel " << i << ": " << decoded.value().pixels[i] << " vs " << grid.heights[i];
}

TEST(FloatHeightmaps, TiffKeepsEveryFloatBitForBit) {
  expectFloatRoundTrip(HeightmapFormat::kTiff, image::FloatImageFormat::kTiff);
}

TEST(FloatHeightmaps, ExrKeepsEveryFloatBitForBit) {
  expectFloatRoundTrip(HeightmapFormat::kExr, image::FloatImageFormat::kExr);
}

TEST(FloatHeightmaps, StartWithTheirFormatsMagicBytes) {
  EXPECT_EQ(encode(row({1.0f}), HeightmapFormat::kTiff).substr(0, 4), std::string("II*\0", 4));
  EXPECT_EQ(encode(row({1.0f}), HeightmapFormat::kExr).substr(0, 4), "\x76\x2f\x31\x01");
}

TEST(FloatHeightmaps, GarbageDoesNotDecode) {
  const auto decoded = image::decodeFloatImage("not an image", image::FloatImageFormat::kTiff);
  ASSERT_FALSE(decoded.ok());
  EXPECT_EQ(decoded.error().code, ErrorCode::kInvalidInput);
}

// ---------------------------------------------------------------------------------------------
// Errors, determinism, MIME types

TEST(HeightmapEncoder, RejectsNaNNamingThePixel) {
  HeightGrid grid = terrain(5, 4);
  grid.heights[2 * 5 + 3] = std::numeric_limits<float>::quiet_NaN();
  for (const HeightmapFormat format : kAllFormats) {
    const auto bytes = encodeHeightmap(grid, format);
    ASSERT_FALSE(bytes.ok());
    EXPECT_EQ(bytes.error().code, ErrorCode::kInvalidInput);
    EXPECT_NE(bytes.error().message.find("pixel (3, 2) is NaN"), std::string::npos)
        << bytes.error().message;
  }
}

TEST(HeightmapEncoder, RejectsInfinity) {
  const auto bytes = encodeHeightmap(row({0.0f, -std::numeric_limits<float>::infinity()}),
                                     HeightmapFormat::kTerrainRgb);
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(bytes.error().message.find("pixel (1, 0) is infinite"), std::string::npos)
      << bytes.error().message;
}

TEST(HeightmapEncoder, RejectsBadDimensions) {
  const HeightGrid bad[] = {{0, 4, {}},
                            {4, 0, {}},
                            {-1, 4, {}},
                            {4097, 1, std::vector<float>(4097)},
                            {1, 4097, std::vector<float>(4097)},
                            {4, 4, std::vector<float>(15)},
                            {4, 4, std::vector<float>(17)}};
  for (const HeightGrid& grid : bad)
    for (const HeightmapFormat format : kAllFormats) {
      const auto bytes = encodeHeightmap(grid, format);
      ASSERT_FALSE(bytes.ok()) << grid.width << "x" << grid.height;
      EXPECT_EQ(bytes.error().code, ErrorCode::kInvalidInput);
      EXPECT_NE(bytes.error().message.find(std::to_string(grid.width) + "x" +
                                           std::to_string(grid.height)),
                std::string::npos)
          << bytes.error().message;
    }
}

TEST(HeightmapEncoder, AcceptsTheLargestSide) {
  // 4096 × 2 heights in steps of 0.5 m (exact in every format): every pixel decodes to its own.
  HeightGrid grid{4096, 2, {}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4096; ++x)
      grid.heights.push_back(static_cast<float>(0.5 * (x % 1000) + 600.0 * y - 100.0));
  const auto expectHeights = [&](const std::vector<double>& decoded, HeightmapFormat format) {
    ASSERT_EQ(decoded.size(), grid.heights.size()) << static_cast<int>(format);
    for (std::size_t i = 0; i < decoded.size(); ++i)
      ASSERT_NEAR(decoded[i], grid.heights[i], 1e-6) << static_cast<int>(format) << " pixel " << i;
  };
  for (const HeightmapFormat format :
       {HeightmapFormat::kTerrainRgb, HeightmapFormat::kTerrarium, HeightmapFormat::kPng16}) {
    const DecodedPng png = decodePng(encode(grid, format));
    EXPECT_EQ(png.header.width, 4096u);
    EXPECT_EQ(png.header.height, 2u);
    expectHeights(format == HeightmapFormat::kTerrainRgb  ? decodeTerrainRgb(png)
                  : format == HeightmapFormat::kTerrarium ? decodeTerrarium(png)
                                                          : decodePng16(png),
                  format);
  }
  for (const auto& [format, container] :
       {std::pair{HeightmapFormat::kTiff, image::FloatImageFormat::kTiff},
        std::pair{HeightmapFormat::kExr, image::FloatImageFormat::kExr}}) {
    STRAHLER_ASSIGN_OR_ASSERT(const auto decoded,
                              image::decodeFloatImage(encode(grid, format), container));
    EXPECT_EQ(decoded.width, 4096);
    EXPECT_EQ(decoded.height, 2);
    expectHeights({decoded.pixels.begin(), decoded.pixels.end()}, format);
  }
}

TEST(HeightmapEncoder, RejectsAnUnknownFormat) {
  const auto bytes = encodeHeightmap(row({1.0f}), static_cast<HeightmapFormat>(99));
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.error().code, ErrorCode::kInvalidInput);
}

TEST(HeightmapEncoder, SameGridSameBytes) {
  const HeightGrid grid = terrain(130, 70);
  for (const HeightmapFormat format : kAllFormats)
    EXPECT_EQ(encode(grid, format), encode(grid, format)) << static_cast<int>(format);
}

TEST(HeightmapEncoder, CompressesSmoothTerrain) {
  // A 256² tile is 196608 bytes of raw RGB; on gentle relief filtered deflate removes most.
  const std::string bytes = encode(gentleSlope(256, 256), HeightmapFormat::kTerrainRgb);
  EXPECT_LT(bytes.size(), 196608u / 4);
}

TEST(HeightmapEncoder, MimeTypes) {
  EXPECT_STREQ(mimeType(HeightmapFormat::kTerrainRgb), "image/png");
  EXPECT_STREQ(mimeType(HeightmapFormat::kTerrarium), "image/png");
  EXPECT_STREQ(mimeType(HeightmapFormat::kPng16), "image/png");
  EXPECT_STREQ(mimeType(HeightmapFormat::kTiff), "image/tiff");
  EXPECT_STREQ(mimeType(HeightmapFormat::kExr), "image/x-exr");
}

// ---------------------------------------------------------------------------------------------
// Golden files: tests/data/golden/heightmap_16.*; STRAHLER_UPDATE_GOLDEN=1 rewrites them.

/// 16×16 heights from integer arithmetic only (no libm), so the input is the same everywhere;
/// two corners are out of every PNG format's range.
HeightGrid goldenGrid() {
  HeightGrid grid{16, 16, {}};
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      grid.heights.push_back(static_cast<float>((x * 7919 + y * 104729) % 20011) * 0.37f - 1200.0f);
  grid.heights.front() = -20000.0f;
  grid.heights.back() = 1e6f;
  return grid;
}

struct GoldenCase {
  HeightmapFormat format;
  const char* suffix;
};

constexpr GoldenCase kGolden[] = {{HeightmapFormat::kTerrainRgb, "terrainrgb.png"},
                                  {HeightmapFormat::kTerrarium, "terrarium.png"},
                                  {HeightmapFormat::kPng16, "png16.png"},
                                  {HeightmapFormat::kTiff, "tif"},
                                  {HeightmapFormat::kExr, "exr"}};

fs::path goldenPath(const GoldenCase& c) {
  return fs::path(STRAHLER_TEST_DATA_DIR) / "golden" / (std::string("heightmap_16.") + c.suffix);
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool updatingGolden() {
  const char* flag = std::getenv("STRAHLER_UPDATE_GOLDEN");
  return flag != nullptr && std::string(flag) == "1";
}

TEST(HeightmapGolden, MatchesTheCommittedFilesByteForByte) {
  const HeightGrid grid = goldenGrid();
  for (const GoldenCase& c : kGolden) {
    const std::string bytes = encode(grid, c.format);
    const fs::path path = goldenPath(c);
    if (updatingGolden()) {
      fs::create_directories(path.parent_path());
      std::ofstream(path, std::ios::binary) << bytes;
      continue;
    }
    ASSERT_TRUE(fs::exists(path)) << path << " is missing: run with STRAHLER_UPDATE_GOLDEN=1";
    EXPECT_TRUE(readFile(path) == bytes)
        << path << " differs from today's encoding; if the change is intended, rerun with "
        << "STRAHLER_UPDATE_GOLDEN=1 and review the new files";
  }
}

TEST(HeightmapGolden, FloatFilesHoldTheGridBitForBit) {
  // Guards the golden TIFF/EXR themselves: whatever bytes a library upgrade produces, the
  // committed files must still decode to exactly the golden grid.
  const HeightGrid grid = goldenGrid();
  const std::pair<const GoldenCase&, image::FloatImageFormat> cases[] = {
      {kGolden[3], image::FloatImageFormat::kTiff}, {kGolden[4], image::FloatImageFormat::kExr}};
  for (const auto& [golden, container] : cases) {
    STRAHLER_ASSIGN_OR_ASSERT(const auto decoded,
                              image::decodeFloatImage(readFile(goldenPath(golden)), container));
    EXPECT_EQ(decoded.pixels, grid.heights) << goldenPath(golden);
  }
}

TEST(RgbPng, DecodesToItsPixelsAsAnEightBitRgbPngWithNoAncillaryChunks) {
  std::vector<std::uint8_t> pixels;
  for (int i = 0; i < 37 * 11 * 3; ++i)
    pixels.push_back(static_cast<std::uint8_t>((i * 37) ^ (i >> 3)));
  const auto bytes = encodeRgbPng(pixels, 37, 11);
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  const DecodedPng png = decodePng(bytes.value());
  EXPECT_EQ(png.header.width, 37u);
  EXPECT_EQ(png.header.height, 11u);
  EXPECT_EQ(png.header.bit_depth, 8);
  EXPECT_EQ(png.header.color_type, SPNG_COLOR_TYPE_TRUECOLOR);
  EXPECT_EQ(png.samples, pixels);
  for (const std::string& type : chunkTypes(bytes.value()))
    EXPECT_TRUE(type == "IHDR" || type == "IDAT" || type == "IEND") << type;
  EXPECT_EQ(encodeRgbPng(pixels, 37, 11).value(), bytes.value()); // deterministic
}

TEST(RgbPng, RejectsBadDimensionsAndByteCounts) {
  EXPECT_EQ(encodeRgbPng({}, 0, 1).error().code, ErrorCode::kInvalidInput);
  EXPECT_EQ(encodeRgbPng(std::vector<std::uint8_t>(3 * 4097), 4097, 1).error().code,
            ErrorCode::kInvalidInput);
  const auto wrong = encodeRgbPng(std::vector<std::uint8_t>(11), 2, 2);
  ASSERT_FALSE(wrong.ok());
  EXPECT_EQ(wrong.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(wrong.error().message.find("11 bytes"), std::string::npos);
}

} // namespace
} // namespace strahler::encoding
