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

/// Writes an RGB image as PNG (compression level 6); kInvalidInput when pixels.size() is not
/// width*height*3, kIoError when the file cannot be written.
base::Status writePng(const std::string& path, const RgbImage& image);

} // namespace strahler::image
