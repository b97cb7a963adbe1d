#include "json_util.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <new>
#include <optional>
#include <utility>
#include <vector>

namespace strahler::input::detail {
namespace {

using base::ErrorCode;
using base::makeError;

/// Offset of the first '[' or '{' (outside strings) nested deeper than maxDepth.
std::size_t findTooDeep(std::string_view text, int maxDepth) noexcept {
  int depth = 0;
  bool inString = false;
  bool escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > maxDepth)
        return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return text.size();
}

/// `text` with every byte that is not part of a well-formed UTF-8 sequence replaced by '?',
/// so messages stay printable and serialisable as JSON.
std::string validUtf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    std::size_t length = c < 0x80           ? 1
                         : (c >> 5) == 0x6  ? 2
                         : (c >> 4) == 0xe  ? 3
                         : (c >> 3) == 0x1e ? 4
                                            : 0;
    for (std::size_t k = 1; k < length; ++k)
      if (i + k >= text.size() || (static_cast<unsigned char>(text[i + k]) >> 6) != 0x2)
        length = 0;
    if (length == 0) {
      out += '?';
      ++i;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

/// nlohmann's message without its "[json.exception.parse_error.101] " prefix, cut to a
/// readable length (it quotes the last token read, which can be megabytes long).
std::string stripExceptionPrefix(const char* what) {
  constexpr std::size_t kMaxLength = 300;
  std::string_view text(what);
  if (!text.empty() && text.front() == '[') {
    const std::size_t end = text.find("] ");
    if (end != std::string_view::npos)
      text.remove_prefix(end + 2);
  }
  if (text.size() > kMaxLength)
    return validUtf8(text.substr(0, kMaxLength)) + "...";
  return validUtf8(text);
}

/// A SAX consumer that builds the DOM like nlohmann's own, but caps nesting and the number
/// of values, and refuses duplicate keys, reporting the first fault as a base::Error.
class CappedDomBuilder {
public:
  CappedDomBuilder(Json& root, std::string_view text, std::string_view what,
                   const JsonLimits& limits)
      : root_(root), text_(text), what_(what), limits_(limits) {}

  bool null() { return insert(Json(nullptr)) != nullptr; }
  bool boolean(bool v) { return insert(Json(v)) != nullptr; }
  bool number_integer(Json::number_integer_t v) { return insert(Json(v)) != nullptr; }
  bool number_unsigned(Json::number_unsigned_t v) { return insert(Json(v)) != nullptr; }
  bool number_float(Json::number_float_t v, const Json::string_t&) {
    return insert(Json(v)) != nullptr;
  }
  bool string(Json::string_t& v) { return insert(Json(std::move(v))) != nullptr; }
  bool binary(Json::binary_t&) {
    return fail(ErrorCode::kInvalidInput, "binary values are not JSON");
  }
  bool start_object(std::size_t) { return open(Json::object()); }
  bool start_array(std::size_t) { return open(Json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(Json::string_t& k) {
    if (stack_.back()->contains(k))
      return fail(ErrorCode::kInvalidInput,
                  "duplicate key \"" + printable(k) + "\" at " + printable(path(k), 200));
    pendingKey_ = std::move(k);
    return true;
  }
  bool parse_error(std::size_t position, const std::string& token, const Json::exception& ex) {
    if (ex.id == 406)
      return fail(ErrorCode::kInvalidInput, "number " + printable(token) + " at byte " +
                                                std::to_string(position) +
                                                " is too large (it overflows to infinity)");
    return fail(ErrorCode::kInvalidInput, "not valid JSON at byte " + std::to_string(position) +
                                              ": " + stripExceptionPrefix(ex.what()));
  }

  const std::optional<base::Error>& error() const noexcept { return error_; }

private:
  bool fail(ErrorCode code, const std::string& message) {
    if (!error_)
      error_ = makeError(code, std::string(what_) + ": " + message);
    return false;
  }

  std::string path(std::string_view last) const {
    std::string p;
    for (const std::string& s : segments_)
      p += "/" + s;
    return p + "/" + std::string(last);
  }

  Json* insert(Json&& value) {
    if (++values_ > limits_.maxValues) {
      fail(ErrorCode::kLimitExceeded,
           "more than " + std::to_string(limits_.maxValues) + " JSON values" +
               (limits_.valuesNote.empty() ? "" : " (" + limits_.valuesNote + ")"));
      return nullptr;
    }
    if (stack_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Json& parent = *stack_.back();
    if (parent.is_array()) {
      auto& array = parent.get_ref<Json::array_t&>();
      array.push_back(std::move(value));
      return &array.back();
    }
    auto& object = parent.get_ref<Json::object_t&>();
    return &object.emplace(std::move(pendingKey_), std::move(value)).first->second;
  }

  bool open(Json&& container) {
    if (static_cast<int>(stack_.size()) >= limits_.maxDepth) {
      const std::size_t at = findTooDeep(text_, limits_.maxDepth);
      return fail(ErrorCode::kLimitExceeded, "JSON nested deeper than " +
                                                 std::to_string(limits_.maxDepth) +
                                                 " levels (at byte " + std::to_string(at) + ")");
    }
    std::string segment; // where the container sits in its parent, for error paths
    if (!stack_.empty())
      segment = stack_.back()->is_array() ? std::to_string(stack_.back()->size()) : pendingKey_;
    Json* added = insert(std::move(container));
    if (added == nullptr)
      return false;
    if (!stack_.empty())
      segments_.push_back(std::move(segment));
    stack_.push_back(added);
    return true;
  }

  bool close() {
    stack_.pop_back();
    if (!stack_.empty())
      segments_.pop_back(); // the closed container was not the root
    return true;
  }

  Json& root_;
  std::string_view text_;
  std::string_view what_;
  const JsonLimits& limits_;
  std::vector<Json*> stack_;          // open containers; pointers stay valid while open
  std::vector<std::string> segments_; // path to the innermost open container
  std::string pendingKey_;
  std::size_t values_ = 0;
  std::optional<base::Error> error_;
};

} // namespace

base::Result<Json> parseJson(std::string_view text, std::string_view what,
                             const JsonLimits& limits) {
  if (text.size() > limits.maxBytes)
    return makeError(ErrorCode::kLimitExceeded, std::string(what) + ": " +
                                                    std::to_string(text.size()) +
                                                    " bytes is more than the limit of " +
                                                    std::to_string(limits.maxBytes) + " bytes");
  try {
    Json root;
    CappedDomBuilder builder(root, text, what, limits);
    const bool ok = Json::sax_parse(text.begin(), text.end(), &builder);
    if (builder.error())
      return *builder.error();
    if (!ok)
      return makeError(ErrorCode::kInvalidInput, std::string(what) + ": not valid JSON");
    return root;
  } catch (const std::bad_alloc&) {
    return makeError(ErrorCode::kLimitExceeded, std::string(what) + ": out of memory");
  } catch (const std::exception& e) {
    return makeError(ErrorCode::kInvalidInput,
                     std::string(what) + ": not valid JSON: " + stripExceptionPrefix(e.what()));
  }
}

const char* describeType(const Json& value) noexcept {
  switch (value.type()) {
  case Json::value_t::null:
    return "null";
  case Json::value_t::object:
    return "an object";
  case Json::value_t::array:
    return "an array";
  case Json::value_t::string:
    return "a string";
  case Json::value_t::boolean:
    return "a boolean";
  case Json::value_t::number_integer:
  case Json::value_t::number_unsigned:
  case Json::value_t::number_float:
    return "a number";
  case Json::value_t::binary:
    return "binary data";
  case Json::value_t::discarded:
    return "a discarded value";
  }
  return "an unknown value";
}

std::string formatNumber(double value) {
  if (!std::isfinite(value))
    return "null";
  if (value == 0.0)
    return "0";
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::string quoteJson(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
    case '"':
      out += "\\\"";
      break;
    case '\\':
      out += "\\\\";
      break;
    case '\n':
      out += "\\n";
      break;
    case '\t':
      out += "\\t";
      break;
    case '\r':
      out += "\\r";
      break;
    default:
      if (static_cast<unsigned char>(c) < 0x20) {
        std::array<char, 8> escape{};
        std::snprintf(escape.data(), escape.size(), "\\u%04x", static_cast<unsigned>(c));
        out += escape.data();
      } else {
        out += c;
      }
    }
  }
  return out + "\"";
}

std::string printable(std::string_view text, std::size_t maxChars) {
  const bool cut = text.size() > maxChars;
  std::string quoted = quoteJson(validUtf8(text.substr(0, maxChars)));
  quoted = quoted.substr(1, quoted.size() - 2);
  return cut ? quoted + "..." : quoted;
}

base::Result<geometry::Vec2> parsePosition(const Json& value, const std::string& where) {
  if (!value.is_array())
    return makeError(ErrorCode::kInvalidInput,
                     where + ": a position must be an array [lon, lat], got " +
                         describeType(value));
  const std::size_t n = value.size();
  if (n != 2 && n != 3)
    return makeError(ErrorCode::kInvalidInput,
                     where + ": position has " + std::to_string(n) +
                         (n == 1 ? " number" : " numbers") +
                         ", a position needs 2 (lon, lat) or 3 (lon, lat, altitude)");
  std::array<double, 2> lonLat{};
  for (std::size_t i = 0; i < n; ++i) {
    const Json& c = value[i];
    if (!c.is_number())
      return makeError(ErrorCode::kInvalidInput, where + ": coordinate " + std::to_string(i) +
                                                     " is " + describeType(c) + ", not a number");
    const double v = c.get<double>();
    if (!std::isfinite(v))
      return makeError(ErrorCode::kInvalidInput,
                       where + ": coordinate " + std::to_string(i) + " is not a finite number");
    if (i < 2)
      lonLat[i] = v;
  }
  if (!(lonLat[0] >= -180.0 && lonLat[0] <= 180.0))
    return makeError(ErrorCode::kOutOfRange,
                     where + ": longitude " + formatNumber(lonLat[0]) + " is outside [-180, 180]");
  if (!(lonLat[1] >= -90.0 && lonLat[1] <= 90.0)) {
    // A latitude past the pole with a longitude that could be one: most likely [lat, lon].
    const bool swapped = lonLat[0] >= -90.0 && lonLat[0] <= 90.0;
    return makeError(ErrorCode::kOutOfRange,
                     where + ": latitude " + formatNumber(lonLat[1]) + " is outside [-90, 90]" +
                         (swapped ? "; are the coordinates swapped? GeoJSON positions are "
                                    "[longitude, latitude]"
                                  : ""));
  }
  return geometry::Vec2{lonLat[0], lonLat[1]};
}

} // namespace strahler::input::detail
