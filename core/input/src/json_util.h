#pragma once
// Private to core/input: the one boundary where JSON text becomes nlohmann::json. Every
// nlohmann error (syntax, overflow, depth) becomes a base::Error here; callers only ever
// see a bounded, depth-capped DOM.

#include "strahler/base/result.h"
#include "strahler/geometry/vec2.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace strahler::input::detail {

using Json = nlohmann::json;

/// Caps applied while parsing one JSON document.
struct JsonLimits {
  std::size_t maxBytes = 64u << 20; ///< Size of the text.
  int maxDepth = 64;                ///< Nesting of arrays and objects.
  std::size_t maxValues = 1u << 20; ///< Values of any kind (bounds the DOM's memory).
  std::string valuesNote;           ///< Why maxValues is what it is, for the error message.
};

/// Parses `text`; errors start with `what` ("coastline", "params", ...) and give the byte
/// position (syntax, overflow, nesting) or the JSON path (duplicate keys). Never throws.
base::Result<Json> parseJson(std::string_view text, std::string_view what,
                             const JsonLimits& limits);

/// "a string", "an array", "null", ... for messages.
const char* describeType(const Json& value) noexcept;

/// Shortest text that reads back as exactly `value` ("1000", "0.1", "1e+21"); -0 prints as
/// "0" and non-finite values as "null" (JSON has no NaN or infinity).
std::string formatNumber(double value);

/// `text` as a JSON string literal, quotes included.
std::string quoteJson(std::string_view text);

/// User text for an error message: control characters escaped, cut to `maxChars` bytes
/// with "..." (a key or type name can be megabytes long).
std::string printable(std::string_view text, std::size_t maxChars = 64);

/// Parses a GeoJSON position: an array of 2 or 3 finite numbers (the third, altitude, is
/// ignored) with lon in [-180, 180] and lat in [-90, 90]. `where` prefixes errors.
base::Result<geometry::Vec2> parsePosition(const Json& value, const std::string& where);

/// a + b, saturating at SIZE_MAX (for caps derived from user-set limits).
inline std::size_t saturatingAdd(std::size_t a, std::size_t b) noexcept {
  return a > static_cast<std::size_t>(-1) - b ? static_cast<std::size_t>(-1) : a + b;
}

/// a * b, saturating at SIZE_MAX.
inline std::size_t saturatingMul(std::size_t a, std::size_t b) noexcept {
  return b != 0 && a > static_cast<std::size_t>(-1) / b ? static_cast<std::size_t>(-1) : a * b;
}

} // namespace strahler::input::detail
