#include "strahler/http/http_types.h"

#include <cstdint>
#include <string_view>

namespace strahler::http {
namespace {

constexpr std::string_view kReplacementCharacter = "\xEF\xBF\xBD";

/// Length of the valid UTF-8 sequence starting at `s[i]`, or 0 when it is malformed.
std::size_t utf8SequenceLength(std::string_view s, std::size_t i) {
  const auto lead = static_cast<unsigned char>(s[i]);
  std::size_t length = 0;
  std::uint32_t minimum = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
    minimum = 0x80;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    minimum = 0x800;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    minimum = 0x10000;
  } else {
    return 0;
  }
  if (i + length > s.size())
    return 0;
  std::uint32_t code = lead & (0xFFu >> (length + 1));
  for (std::size_t k = 1; k < length; ++k) {
    const auto next = static_cast<unsigned char>(s[i + k]);
    if ((next & 0xC0) != 0x80)
      return 0;
    code = (code << 6) | (next & 0x3Fu);
  }
  const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
  return (code < minimum || code > 0x10FFFF || surrogate) ? 0 : length;
}

/// Appends `c` (ASCII) to a JSON string body, escaped as RFC 8259 requires.
void appendAsciiEscaped(std::string& out, char c) {
  static constexpr char kHex[] = "0123456789abcdef";
  switch (c) {
  case '"':
    out += "\\\"";
    return;
  case '\\':
    out += "\\\\";
    return;
  case '\n':
    out += "\\n";
    return;
  case '\r':
    out += "\\r";
    return;
  case '\t':
    out += "\\t";
    return;
  default:
    break;
  }
  const auto byte = static_cast<unsigned char>(c);
  if (byte < 0x20 || byte == 0x7F) {
    out += "\\u00";
    out += kHex[byte >> 4];
    out += kHex[byte & 0xF];
  } else {
    out += c;
  }
}

/// `text` as the inside of a JSON string: escaped, and invalid UTF-8 replaced by U+FFFD so that
/// client-supplied bytes quoted in a message can never make the body invalid JSON.
std::string jsonStringContent(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 8);
  for (std::size_t i = 0; i < text.size();) {
    if (static_cast<unsigned char>(text[i]) < 0x80) {
      appendAsciiEscaped(out, text[i++]);
      continue;
    }
    const std::size_t length = utf8SequenceLength(text, i);
    if (length == 0) {
      out += kReplacementCharacter;
      ++i;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

} // namespace

Response errorResponse(int status, const std::string& message) {
  Response response;
  response.status = status;
  response.headers.emplace_back("Content-Type", "application/json");
  if (status >= 500)
    response.headers.emplace_back("Cache-Control", "no-store");
  response.body = "{\"error\": \"" + jsonStringContent(message) + "\"}";
  response.route = "error";
  return response;
}

} // namespace strahler::http
