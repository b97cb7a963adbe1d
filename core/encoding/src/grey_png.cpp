#include "strahler/encoding/grey_png.h"

#include "png_encoder.h"

namespace strahler::encoding {
namespace {

/// The largest side of a heightmap tile (heightmap_encoder.cpp), for pictures as well.
constexpr int kMaxSide = 4096;

/// kInvalidInput unless width × height is a valid picture of `count` samples.
base::Status checkShape(std::size_t count, int width, int height) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide)
    return base::makeError(base::ErrorCode::kInvalidInput, "grey picture " + size +
                                                               ": width and height must be 1.." +
                                                               std::to_string(kMaxSide));
  if (count != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    return base::makeError(base::ErrorCode::kInvalidInput, "grey picture " + size + ": " +
                                                               std::to_string(count) +
                                                               " samples, expected width*height");
  return base::Ok{};
}

} // namespace

base::Result<std::string> encodeGrey8Png(const std::vector<std::uint8_t>& samples, int width,
                                         int height) {
  STRAHLER_RETURN_IF_ERROR(checkShape(samples.size(), width, height));
  return detail::encodePng(samples, width, height, detail::PngLayout::kGray8);
}

base::Result<std::string> encodeGrey16Png(const std::vector<std::uint16_t>& samples, int width,
                                          int height) {
  STRAHLER_RETURN_IF_ERROR(checkShape(samples.size(), width, height));
  std::vector<std::uint8_t> bytes(samples.size() * 2);
  for (std::size_t i = 0; i < samples.size(); ++i) { // PNG stores 16-bit samples big-endian
    bytes[2 * i] = static_cast<std::uint8_t>(samples[i] >> 8);
    bytes[2 * i + 1] = static_cast<std::uint8_t>(samples[i] & 0xffu);
  }
  return detail::encodePng(bytes, width, height, detail::PngLayout::kGray16);
}

base::Result<std::string> encodeRgba8Png(const std::vector<std::uint8_t>& samples, int width,
                                         int height) {
  STRAHLER_RETURN_IF_ERROR(checkShape(samples.size() / 4, width, height));
  if (samples.size() % 4 != 0)
    return base::makeError(base::ErrorCode::kInvalidInput,
                           "RGBA picture: the byte count is not a multiple of 4");
  return detail::encodePng(samples, width, height, detail::PngLayout::kRgba8);
}

} // namespace strahler::encoding
