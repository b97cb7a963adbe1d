#include "strahler/encoding/rgb_png.h"

#include "png_encoder.h"

namespace strahler::encoding {
namespace {

/// The largest side of a heightmap tile (heightmap_encoder.cpp), for pictures as well.
constexpr int kMaxSide = 4096;

} // namespace

base::Result<std::string> encodeRgbPng(const std::vector<std::uint8_t>& pixels, int width,
                                       int height) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide)
    return base::makeError(base::ErrorCode::kInvalidInput, "rgb picture " + size +
                                                               ": width and height must be 1.." +
                                                               std::to_string(kMaxSide));
  if (pixels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3)
    return base::makeError(base::ErrorCode::kInvalidInput, "rgb picture " + size + ": " +
                                                               std::to_string(pixels.size()) +
                                                               " bytes, expected width*height*3");
  return detail::encodePng(pixels, width, height, detail::PngLayout::kRgb8);
}

} // namespace strahler::encoding
