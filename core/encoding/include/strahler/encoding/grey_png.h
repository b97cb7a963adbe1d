#pragma once

#include "strahler/base/result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace strahler::encoding {

/// Encodes an 8-bit grey picture (`samples`: width · height bytes, row-major, top row first) as
/// a PNG with no ancillary chunks, by the heightmap tiles' libspng path and settings.
/// kInvalidInput when width or height is outside 1 … 4096 or the count is not width · height;
/// kInternal when the codec fails. Deterministic: the same samples give the same bytes.
base::Result<std::string> encodeGrey8Png(const std::vector<std::uint8_t>& samples, int width,
                                         int height);

/// Encodes a 16-bit grey picture (`samples`: width · height values, row-major, top row first)
/// as a PNG with no ancillary chunks (the png16 heightmaps' path). Errors as encodeGrey8Png.
base::Result<std::string> encodeGrey16Png(const std::vector<std::uint16_t>& samples, int width,
                                          int height);

/// Encodes an 8-bit RGBA picture (`samples`: width · height · 4 bytes R, G, B, A, row-major,
/// top row first; A is data, not premultiplied) as a PNG with no ancillary chunks (the splat
/// alphamaps of export-heightmap). Errors as encodeGrey8Png.
base::Result<std::string> encodeRgba8Png(const std::vector<std::uint8_t>& samples, int width,
                                         int height);

} // namespace strahler::encoding
