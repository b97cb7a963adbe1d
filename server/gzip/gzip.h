#pragma once

#include "strahler/base/result.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace strahler::gzip {

/// How hard compress() works.
enum class Level {
  kFastest,  ///< zlib level 1 (Iceland's 54 MB rivers.geojson: 17.0 MB in 0.85 s).
  kSmallest, ///< zlib level 9 (small PMTiles directories written once).
};

/// `bytes` as one gzip member (RFC 1952) with mtime 0, so equal input gives equal output.
std::string compress(std::string_view bytes, Level level);

/// The bytes of the gzip member in `packed`; kCorrupt when it is damaged, truncated or followed
/// by other bytes, kInvalidInput when it would inflate to more than `maxBytes`.
base::Result<std::string> decompress(std::string_view packed, std::size_t maxBytes);

} // namespace strahler::gzip
