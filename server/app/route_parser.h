#pragma once

#include "strahler/base/result.h"

#include <cstdint>
#include <map>
#include <string>
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

} // namespace strahler::app
