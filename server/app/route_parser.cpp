#include "route_parser.h"

namespace strahler::app {
namespace {

base::Error malformed(const std::string& why) {
  return base::makeError(base::ErrorCode::kInvalidInput, "malformed request target: " + why);
}

int hexValue(char c) {
  if (c >= '0' && c <= '9')
    return c - '0';
  if (c >= 'a' && c <= 'f')
    return c - 'a' + 10;
  if (c >= 'A' && c <= 'F')
    return c - 'A' + 10;
  return -1;
}

base::Result<std::string> percentDecode(const std::string& text, bool plusIsSpace) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      return malformed("control character");
    if (c == '+' && plusIsSpace) {
      out += ' ';
    } else if (c == '%') {
      const int hi = i + 1 < text.size() ? hexValue(text[i + 1]) : -1;
      const int lo = i + 2 < text.size() ? hexValue(text[i + 2]) : -1;
      if (hi < 0 || lo < 0)
        return malformed("invalid percent escape");
      const char decoded = static_cast<char>(hi * 16 + lo);
      if (decoded == '\0')
        return malformed("NUL in percent escape");
      out += decoded;
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

} // namespace

base::Result<ParsedTarget> parseTarget(const std::string& target) {
  if (target.empty() || target[0] != '/')
    return malformed("must start with '/'");
  const std::size_t q = target.find('?');
  const std::string path = target.substr(0, q);
  ParsedTarget out;
  out.trailingSlash = path.size() > 1 && path.back() == '/';
  std::size_t start = 1;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    STRAHLER_ASSIGN_OR_RETURN(std::string segment,
                              percentDecode(path.substr(start, end - start), false));
    if (segment == "." || segment == "..")
      return malformed("dot segment");
    if (segment.find('/') != std::string::npos)
      return malformed("encoded '/' in a segment");
    const bool last = end == path.size();
    if (segment.empty() && !last)
      return malformed("empty segment");
    if (!segment.empty())
      out.segments.push_back(std::move(segment));
    start = end + 1;
  }
  if (q == std::string::npos)
    return out;
  const std::string query = target.substr(q + 1);
  std::size_t begin = 0;
  while (begin < query.size()) {
    const std::size_t end = std::min(query.find('&', begin), query.size());
    const std::string pair = query.substr(begin, end - begin);
    if (!pair.empty()) {
      const std::size_t eq = pair.find('=');
      STRAHLER_ASSIGN_OR_RETURN(std::string key, percentDecode(pair.substr(0, eq), true));
      STRAHLER_ASSIGN_OR_RETURN(
          std::string value,
          percentDecode(eq == std::string::npos ? "" : pair.substr(eq + 1), true));
      if (out.query.count(key))
        return base::makeError(base::ErrorCode::kInvalidInput,
                               "query parameter '" + key.substr(0, 64) + "' is given twice");
      out.query.emplace(std::move(key), std::move(value));
    }
    begin = end + 1;
  }
  return out;
}

base::Result<std::int64_t> parseDecimal(const std::string& text, int maxDigits) {
  if (text.empty() || text.size() > static_cast<std::size_t>(maxDigits))
    return base::makeError(base::ErrorCode::kInvalidInput,
                           "'" + text.substr(0, 32) +
                               "' is not a non-negative integer of at most " +
                               std::to_string(maxDigits) + " digits");
  std::int64_t v = 0;
  for (char c : text) {
    if (c < '0' || c > '9')
      return base::makeError(base::ErrorCode::kInvalidInput,
                             "'" + text.substr(0, 32) + "' is not a non-negative integer");
    v = v * 10 + (c - '0');
  }
  if (text.size() > 1 && text[0] == '0')
    return base::makeError(base::ErrorCode::kInvalidInput,
                           "'" + text + "' has a leading zero (write " + std::to_string(v) + ")");
  return v;
}

base::Result<geometry::TileId> parseTileCoordinates(const std::string& z, const std::string& x,
                                                    const std::string& y) {
  auto zoom = parseDecimal(z, 2), column = parseDecimal(x, 10), row = parseDecimal(y, 10);
  for (auto* v : {&zoom, &column, &row})
    if (!*v)
      return base::makeError(base::ErrorCode::kInvalidInput,
                             "tile coordinate " + v->error().message);
  return geometry::TileId{static_cast<int>(zoom.value()), column.value(), row.value()};
}

base::Result<geometry::TileId> parseZxy(std::span<const std::string> zxy, std::string_view suffix,
                                        std::string_view tile) {
  STRAHLER_ASSERT(zxy.size() == 3, "parseZxy takes the segments {z}, {x} and {y}{suffix}");
  const std::string& last = zxy[2];
  if (last.size() <= suffix.size() ||
      last.compare(last.size() - suffix.size(), suffix.size(), suffix) != 0)
    return base::makeError(base::ErrorCode::kInvalidInput,
                           std::string(tile) + " is named {y}" + std::string(suffix));
  return parseTileCoordinates(zxy[0], zxy[1], last.substr(0, last.size() - suffix.size()));
}

} // namespace strahler::app
