#include "result_matchers.h"

#include "strahler/image/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace strahler::image {
namespace {

namespace fs = std::filesystem;
using base::ErrorCode;

/// A fresh folder under the build tree for this test's files.
fs::path tempDir() {
  const fs::path dir = fs::path(STRAHLER_BINARY_DIR) / "test_tmp" / "image_test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// A minimal uncompressed little-endian TIFF with one 16-bit grey channel.
std::string tiff16(std::uint32_t width, std::uint32_t height,
                   const std::vector<std::uint16_t>& values) {
  std::string bytes;
  const auto put16 = [&](std::uint32_t v) {
    bytes += static_cast<char>(v & 0xff);
    bytes += static_cast<char>((v >> 8) & 0xff);
  };
  const auto put32 = [&](std::uint32_t v) {
    put16(v & 0xffff);
    put16(v >> 16);
  };
  const auto entry = [&](std::uint32_t tag, std::uint32_t type, std::uint32_t value) {
    put16(tag);
    put16(type);
    put32(1);
    put32(value); // a SHORT sits in the low bytes of the value field
  };
  constexpr std::uint32_t kShort = 3, kLong = 4, kEntries = 9;
  const std::uint32_t dataOffset = 8 + 2 + kEntries * 12 + 4;
  bytes += "II";
  put16(42);
  put32(8);
  put16(kEntries);
  entry(256, kShort, width);             // ImageWidth
  entry(257, kShort, height);            // ImageLength
  entry(258, kShort, 16);                // BitsPerSample
  entry(259, kShort, 1);                 // Compression: none
  entry(262, kShort, 1);                 // Photometric: black is zero
  entry(273, kLong, dataOffset);         // StripOffsets
  entry(277, kShort, 1);                 // SamplesPerPixel
  entry(278, kShort, height);            // RowsPerStrip
  entry(279, kLong, width * height * 2); // StripByteCounts
  put32(0);                              // no next IFD
  for (std::uint16_t v : values)
    put16(v);
  return bytes;
}

/// A grayscale PFM: little-endian floats (negative scale), bottom row first.
std::string pfm(int width, int height, const std::vector<float>& topRowFirst) {
  std::string bytes = "Pf\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
  for (int y = height - 1; y >= 0; --y)
    for (int x = 0; x < width; ++x) {
      char raw[4];
      std::memcpy(raw, &topRowFirst[static_cast<std::size_t>(y * width + x)], 4);
      bytes.append(raw, 4); // x86 and arm64 are little-endian
    }
  return bytes;
}

RgbImage gradient(int width, int height) {
  RgbImage image{width, height, {}};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      image.pixels.push_back(static_cast<std::uint8_t>(40 * x + 100 * y));
      image.pixels.push_back(7);
      image.pixels.push_back(250);
    }
  return image;
}

TEST(Image, PngRoundTripReturnsTheFirstChannelNormalised) {
  const std::string path = (tempDir() / "gradient.png").string();
  STRAHLER_ASSERT_OK(writePng(path, gradient(3, 2)));
  STRAHLER_ASSIGN_OR_ASSERT(auto read, readGrayImage(path));
  const GrayImage& image = read;
  ASSERT_EQ(image.width, 3);
  ASSERT_EQ(image.height, 2);
  ASSERT_EQ(image.pixels.size(), 6u);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      EXPECT_FLOAT_EQ(image.at(x, y), static_cast<float>(40 * x + 100 * y) / 255.0f)
          << "pixel " << x << ", " << y;
}

TEST(Image, SixteenBitImagesAreNormalisedToUnitRange) {
  const fs::path path = tempDir() / "depth.tif";
  writeBytes(path, tiff16(3, 1, {0, 65535, 32768}));
  STRAHLER_ASSIGN_OR_ASSERT(auto read, readGrayImage(path.string()));
  EXPECT_FLOAT_EQ(read.at(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(read.at(1, 0), 1.0f);
  EXPECT_NEAR(read.at(2, 0), 32768.0 / 65535.0, 1e-6);
}

TEST(Image, FloatImagesKeepTheirValuesAndRowOrder) {
  const fs::path path = tempDir() / "values.pfm";
  writeBytes(path, pfm(2, 2, {0.25f, 2.5f, -1.0f, 0.75f}));
  STRAHLER_ASSIGN_OR_ASSERT(auto read, readGrayImage(path.string()));
  EXPECT_FLOAT_EQ(read.at(0, 0), 0.25f);
  EXPECT_FLOAT_EQ(read.at(1, 0), 2.5f);
  EXPECT_FLOAT_EQ(read.at(0, 1), -1.0f);
  EXPECT_FLOAT_EQ(read.at(1, 1), 0.75f);
}

TEST(Image, NonFinitePixelsAreRefusedWithTheirPosition) {
  const fs::path path = tempDir() / "nan.pfm";
  writeBytes(path, pfm(2, 1, {0.5f, std::numeric_limits<float>::quiet_NaN()}));
  auto read = readGrayImage(path.string());
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(read.error().message.find("pixel (1, 0) is not a finite number"), std::string::npos)
      << read.error().message;
}

TEST(Image, MissingFileIsNotFoundAndNamesThePath) {
  const std::string path = (tempDir() / "nowhere.png").string();
  auto read = readGrayImage(path);
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().code, ErrorCode::kNotFound);
  EXPECT_NE(read.error().message.find(path), std::string::npos) << read.error().message;
}

TEST(Image, NonImageFileIsAnErrorNamingThePath) {
  const fs::path dir = tempDir();
  for (const char* name : {"notes.txt", "fake.png"}) {
    const fs::path path = dir / name;
    writeBytes(path, "this is not an image\n");
    auto read = readGrayImage(path.string());
    ASSERT_FALSE(read.ok()) << name;
    EXPECT_EQ(read.error().code, ErrorCode::kInvalidInput) << name;
    EXPECT_NE(read.error().message.find(path.string()), std::string::npos) << read.error().message;
  }
}

TEST(Image, TruncatedFileIsAnErrorNamingThePath) {
  const fs::path path = tempDir() / "short.pgm";
  writeBytes(path, "P5\n10 10\n255\nabc");
  auto read = readGrayImage(path.string());
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(read.error().message.find(path.string() + "': cannot read pixels"), std::string::npos)
      << read.error().message;
}

TEST(Image, DirectoryIsAnIoError) {
  const fs::path dir = tempDir();
  auto read = readGrayImage(dir.string());
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().code, ErrorCode::kIoError);
}

TEST(Image, PixelLimitIsEnforced) {
  const std::string path = (tempDir() / "six.png").string();
  STRAHLER_ASSERT_OK(writePng(path, gradient(3, 2)));
  EXPECT_TRUE(readGrayImage(path, 6).ok());
  auto read = readGrayImage(path, 5);
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().code, ErrorCode::kLimitExceeded);
  EXPECT_NE(read.error().message.find("3x2 = 6 pixels"), std::string::npos) << read.error().message;
}

TEST(Image, PixelLimitIsCheckedBeforeReadingPixels) {
  // A header announcing 100000 x 100000 pixels with no pixel data: refusing it as too large
  // (not as truncated) shows the limit is checked before anything is allocated or read.
  const fs::path path = tempDir() / "huge.pgm";
  writeBytes(path, "P5\n100000 100000\n255\n");
  auto read = readGrayImage(path.string());
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().code, ErrorCode::kLimitExceeded) << read.error().message;
}

TEST(Image, WritePngRefusesInconsistentImages) {
  const fs::path dir = tempDir();
  RgbImage image = gradient(3, 2);
  image.pixels.pop_back();
  auto status = writePng((dir / "bad.png").string(), image);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, ErrorCode::kInvalidInput);
  EXPECT_FALSE(writePng((dir / "empty.png").string(), RgbImage{}).ok());
}

TEST(Image, WritePngIntoMissingFolderIsAnIoErrorNamingThePath) {
  const std::string path = (tempDir() / "no" / "such" / "folder.png").string();
  auto status = writePng(path, gradient(2, 2));
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, ErrorCode::kIoError);
  EXPECT_NE(status.error().message.find(path), std::string::npos) << status.error().message;
}

TEST(GrayImage, AtClampsToTheBorder) {
  const GrayImage image{2, 2, {0.0f, 1.0f, 2.0f, 3.0f}};
  EXPECT_EQ(image.at(-5, 0), 0.0f);
  EXPECT_EQ(image.at(9, 0), 1.0f);
  EXPECT_EQ(image.at(1, 9), 3.0f);
  EXPECT_EQ(GrayImage{}.at(0, 0), 0.0f);
}

TEST(GrayImage, SampleIsBilinearBetweenPixelCentres) {
  const GrayImage image{2, 2, {0.0f, 1.0f, 2.0f, 3.0f}};
  EXPECT_FLOAT_EQ(image.sample(0.25, 0.25), 0.0f); // centre of pixel (0, 0)
  EXPECT_FLOAT_EQ(image.sample(0.75, 0.75), 3.0f); // centre of pixel (1, 1)
  EXPECT_FLOAT_EQ(image.sample(0.5, 0.5), 1.5f);
  EXPECT_FLOAT_EQ(image.sample(0.5, 0.25), 0.5f);
  EXPECT_FLOAT_EQ(image.sample(0.0, 0.0), 0.0f);  // edges clamp to the border pixels
  EXPECT_FLOAT_EQ(image.sample(2.0, -1.0), 1.0f); // outside [0, 1]² clamps too
  EXPECT_FLOAT_EQ(image.sample(std::nan(""), 1.0), 2.0f);
}

} // namespace
} // namespace strahler::image
