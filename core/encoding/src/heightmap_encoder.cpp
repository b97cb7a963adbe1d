// Raster heightmap tiles: quantisation to each format's integer code here, PNG bytes in
// png_encoder.cpp (libspng), float TIFF/EXR through strahler::image (OpenImageIO).
#include "strahler/encoding/heightmap_encoder.h"

#include "png_encoder.h"

#include "strahler/base/guarded.h"
#include "strahler/image/image.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace strahler::encoding {
namespace {

using base::ErrorCode;
using base::makeError;

/// Largest tile side accepted: 4096² float heights are 64 MiB, the most one tile may hold.
constexpr int kMaxSide = 4096;
/// Largest 24-bit code (Terrain-RGB and Terrarium pack R·65536 + G·256 + B).
constexpr double kMax24 = 16777215.0;

std::string sizeText(const HeightGrid& grid) {
  return std::to_string(grid.width) + "x" + std::to_string(grid.height);
}

base::Status checkDimensions(const HeightGrid& grid) {
  if (grid.width <= 0 || grid.height <= 0 || grid.width > kMaxSide || grid.height > kMaxSide)
    return makeError(ErrorCode::kInvalidInput, "heightmap grid " + sizeText(grid) +
                                                   ": width and height must be 1.." +
                                                   std::to_string(kMaxSide));
  const std::size_t expected =
      static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height);
  if (grid.heights.size() != expected)
    return makeError(ErrorCode::kInvalidInput,
                     "heightmap grid " + sizeText(grid) + ": " +
                         std::to_string(grid.heights.size()) +
                         " heights, expected width*height = " + std::to_string(expected));
  return base::Ok{};
}

/// A NaN or infinite height is an evaluation bug upstream: refuse it rather than serve a tile
/// that silently shows sea level (or +inf in the float formats).
base::Status checkFinite(const HeightGrid& grid) {
  const auto width = static_cast<std::size_t>(grid.width);
  for (std::size_t i = 0; i < grid.heights.size(); ++i) {
    const float h = grid.heights[i];
    if (!std::isfinite(h))
      return makeError(ErrorCode::kInvalidInput,
                       "heightmap grid " + sizeText(grid) + ": height at pixel (" +
                           std::to_string(i % width) + ", " + std::to_string(i / width) + ") is " +
                           (std::isnan(h) ? "NaN" : "infinite"));
  }
  return base::Ok{};
}

// Heights are widened to double, so h + offset is exact and × 10 rounds once: closer to the
// published real-number formulas than dividing by 0.1, which double cannot represent.

/// std::round(x) clamped to [0, max], without a libm call per pixel (a quarter of a tile's
/// encode time). For x ≥ 0, trunc(x + 0.5) rounds half away from zero exactly like
/// std::round: x + 0.5 can only round up to an integer when x lies within 2^-54 below 0.5,
/// which (h + offset) · 10 cannot reach for any float h.
std::uint32_t roundClamped(double x, double max) {
  return static_cast<std::uint32_t>(std::clamp(x, 0.0, max) + 0.5);
}

/// Terrain-RGB code round((h + 10000) / 0.1), clamped to 24 bits.
std::uint32_t terrainRgbCode(float h) {
  return roundClamped((static_cast<double>(h) + 10000.0) * 10.0, kMax24);
}

/// Terrarium code R·65536 + G·256 + B = floor(256 · (h + 32768)), clamped to 24 bits: the
/// same bytes as R = floor(v / 256), G = floor(v) mod 256, B = floor(frac(v) · 256). Scaling
/// by 256 is exact, and truncation is floor once negatives are clamped away.
std::uint32_t terrariumCode(float h) {
  return static_cast<std::uint32_t>(
      std::clamp((static_cast<double>(h) + 32768.0) * 256.0, 0.0, kMax24));
}

/// 16-bit grey code round((h + 1000) / 0.1), clamped to [0, 65535].
std::uint32_t png16Code(float h) {
  return roundClamped((static_cast<double>(h) + 1000.0) * 10.0, 65535.0);
}

/// Big-endian bytes of each height's code, `Bytes` bytes per pixel.
template <std::size_t Bytes, class CodeFn>
std::vector<std::uint8_t> packCodes(const std::vector<float>& heights, CodeFn code) {
  std::vector<std::uint8_t> samples(heights.size() * Bytes);
  std::uint8_t* out = samples.data();
  for (const float h : heights) {
    const std::uint32_t value = code(h);
    for (std::size_t b = 0; b < Bytes; ++b)
      *out++ = static_cast<std::uint8_t>(value >> (8 * (Bytes - 1 - b)));
  }
  return samples;
}

base::Result<std::string> encodePngFormat(const HeightGrid& grid, HeightmapFormat format) {
  switch (format) {
  case HeightmapFormat::kTerrainRgb:
    return detail::encodePng(packCodes<3>(grid.heights, terrainRgbCode), grid.width, grid.height,
                             detail::PngLayout::kRgb8);
  case HeightmapFormat::kTerrarium:
    return detail::encodePng(packCodes<3>(grid.heights, terrariumCode), grid.width, grid.height,
                             detail::PngLayout::kRgb8);
  default: // kPng16, the only other PNG format
    return detail::encodePng(packCodes<2>(grid.heights, png16Code), grid.width, grid.height,
                             detail::PngLayout::kGray16);
  }
}

base::Result<std::string> encodeUnguarded(const HeightGrid& grid, HeightmapFormat format) {
  STRAHLER_RETURN_IF_ERROR(checkDimensions(grid));
  STRAHLER_RETURN_IF_ERROR(checkFinite(grid));
  switch (format) {
  case HeightmapFormat::kTerrainRgb:
  case HeightmapFormat::kTerrarium:
  case HeightmapFormat::kPng16:
    return encodePngFormat(grid, format);
  case HeightmapFormat::kTiff:
    return image::encodeFloatImage(grid.heights, grid.width, grid.height,
                                   image::FloatImageFormat::kTiff);
  case HeightmapFormat::kExr:
    return image::encodeFloatImage(grid.heights, grid.width, grid.height,
                                   image::FloatImageFormat::kExr);
  }
  return makeError(ErrorCode::kInvalidInput,
                   "unknown heightmap format " + std::to_string(static_cast<int>(format)));
}

} // namespace

base::Result<std::string> encodeHeightmap(const HeightGrid& grid, HeightmapFormat format) {
  const std::string label = "heightmap grid " + sizeText(grid);
  return base::guarded(
      {.label = label, .outOfMemory = "out of memory while encoding", .failurePrefix = ""},
      [&] { return encodeUnguarded(grid, format); });
}

const char* mimeType(HeightmapFormat format) noexcept {
  switch (format) {
  case HeightmapFormat::kTerrainRgb:
  case HeightmapFormat::kTerrarium:
  case HeightmapFormat::kPng16:
    return "image/png";
  case HeightmapFormat::kTiff:
    return "image/tiff";
  case HeightmapFormat::kExr:
    return "image/x-exr";
  }
  return "application/octet-stream";
}

} // namespace strahler::encoding
