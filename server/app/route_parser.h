#pragma once

#include "strahler/base/result.h"
#include "strahler/tiling/tile_scheme.h"

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace strahler::app {

/// A request target split into decoded path segments and query parameters.
struct ParsedTarget {
  std::vector<std::string> segments;        ///< "/worlds/a/tiles" → {"worlds", "a", "tiles"}.
  std::map<std::string, std::string> query; ///< Decoded; each key at most once.
  bool trailingSlash = false;               ///< The path ends with '/' (and is not "/" itself).
};

/// Splits and percent-decodes a request target. kInvalidInput (→ 400) for: not starting
/// with '/', bad or NUL percent escapes, control characters, "." or ".." segments, empty
/// segments inside the path, a query parameter given twice.
base::Result<ParsedTarget> parseTarget(const std::string& target);

/// A decimal integer of at most `maxDigits` digits in its one canonical spelling: no sign, no
/// leading zero ("0" itself is fine), else kInvalidInput.
base::Result<std::int64_t> parseDecimal(const std::string& text, int maxDigits = 10);

/// A tile from the decimal texts of its zoom (at most 2 digits), column and row (at most 10
/// each), by parseDecimal(); else kInvalidInput "tile coordinate …", the first bad one named.
base::Result<geometry::TileId> parseTileCoordinates(const std::string& z, const std::string& x,
                                                    const std::string& y);

/// The tile of a route's last three segments, "{z}/{x}/{y}{suffix}" (`zxy`, three of them):
/// kInvalidInput "<tile> is named {y}<suffix>" (`tile`: e.g. "a vector tile") when the last
/// does not end in `suffix` after at least one character, else parseTileCoordinates().
base::Result<geometry::TileId> parseZxy(std::span<const std::string> zxy, std::string_view suffix,
                                        std::string_view tile);

} // namespace strahler::app
