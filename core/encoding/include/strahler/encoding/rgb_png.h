#pragma once

#include "strahler/base/result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace strahler::encoding {

/// Encodes an 8-bit RGB picture (`pixels`: width · height · 3 bytes, row-major, top row first)
/// as a PNG with no ancillary chunks, by the heightmap tiles' libspng path and settings.
/// kInvalidInput when width or height is outside 1 … 4096 or the byte count is not
/// width · height · 3; kInternal when the codec fails. Deterministic: the same pixels give the
/// same bytes.
base::Result<std::string> encodeRgbPng(const std::vector<std::uint8_t>& pixels, int width,
                                       int height);

} // namespace strahler::encoding
