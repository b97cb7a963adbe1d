#pragma once

#include "strahler/base/result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace strahler::image {

/// A single-channel image, row-major, top row first.
struct GrayImage {
  int width = 0;
  int height = 0;
  std::vector<float> pixels; ///< width*height values; integer formats normalised to [0, 1].

  /// Value at pixel (x, y), clamped to the border.
  float at(int x, int y) const noexcept;
  /// Bilinear sample at normalised coordinates (u, v) in [0, 1]² (clamped), v = 0 at the top
  /// edge; pixel (i, j) is centred on ((i + 0.5) / width, (j + 0.5) / height).
  float sample(double u, double v) const noexcept;
};

/// An 8-bit RGB image, row-major, top row first.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels; ///< width*height*3 bytes.
};

/// Reads the first channel of any image OpenImageIO can read; unsigned and signed integer
/// formats are mapped linearly onto [0, 1], float formats kept as stored. Images larger than
/// `maxPixels` are refused (kLimitExceeded) before their pixels are read; non-finite pixels,
/// volume images and unreadable files are errors naming the path (kNotFound when missing).
base::Result<GrayImage> readGrayImage(const std::string& path, std::size_t maxPixels = 64u << 20);

/// Reads the first channel of any image OpenImageIO can read as stored values (a 16-bit
/// GeoTIFF of heights in metres gives metres: integer formats are NOT normalised), for
/// elevation rasters. Same refusals as readGrayImage (size over `maxPixels` before the pixels
/// are read, non-finite pixels, volume images, unreadable files, kNotFound when missing).
base::Result<GrayImage> readFloatRaster(const std::string& path, std::size_t maxPixels = 64u << 20);

/// Writes an RGB image as PNG (compression level 6); kInvalidInput when pixels.size() is not
/// width*height*3, kIoError when the file cannot be written.
base::Status writePng(const std::string& path, const RgbImage& image);

/// Containers for single-channel float32 images kept in memory (tile bodies).
enum class FloatImageFormat {
  kTiff, ///< TIFF, deflate ("zip") compressed, one float32 channel.
  kExr,  ///< OpenEXR, ZIP compressed (16-scanline blocks), one float32 channel named "Y".
};

/// Encodes `pixels` (width*height float32 values, row-major, top row first) in memory, stored
/// bit for bit. kInvalidInput for width or height ≤ 0 or a pixel count other than
/// width*height; kInternal when OpenImageIO cannot write. Deterministic for one OIIO build.
base::Result<std::string> encodeFloatImage(const std::vector<float>& pixels, int width, int height,
                                           FloatImageFormat format);

/// Decodes the first channel of an in-memory image in `format`, with readGrayImage's rules
/// (float pixels kept as stored, non-finite pixels and more than `maxPixels` refused);
/// kInvalidInput when the bytes are not a readable image of that format.
base::Result<GrayImage> decodeFloatImage(const std::string& bytes, FloatImageFormat format,
                                         std::size_t maxPixels = 64u << 20);

} // namespace strahler::image
