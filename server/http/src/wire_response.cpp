#include "wire_response.h"

#include "net.h"

#include <boost/beast/http/status.hpp>

#include <array>
#include <charconv>
#include <ctime>

namespace strahler::http::detail {
namespace {

/// RFC 9110 token characters (header field names).
bool isTokenChar(char c) noexcept {
  const auto byte = static_cast<unsigned char>(c);
  if (byte <= 0x20 || byte >= 0x7F)
    return false;
  constexpr std::string_view kSeparators = "\"(),/:;<=>?@[\\]{}";
  return kSeparators.find(c) == std::string_view::npos;
}

/// A header the server can write without corrupting the framing (no CR, LF or NUL in it).
bool isWritableHeader(std::string_view name, std::string_view value) noexcept {
  if (name.empty())
    return false;
  for (char c : name)
    if (!isTokenChar(c))
      return false;
  return value.find_first_of(std::string_view("\r\n\0", 3)) == std::string_view::npos;
}

bool hasHeader(const Response& response, std::string_view name) noexcept {
  for (const auto& [key, value] : response.headers)
    if (equalsIgnoreCase(key, name))
      return true;
  return false;
}

/// Statuses whose responses never carry a body or a Content-Length here.
bool isBodiless(int status) noexcept {
  return status == 204 || status == 304;
}

/// `value` without leading and trailing spaces and tabs (optional whitespace, RFC 9110 5.5).
std::string_view trimmed(std::string_view value) noexcept {
  const std::size_t first = value.find_first_not_of(" \t");
  if (first == std::string_view::npos)
    return {};
  return value.substr(first, value.find_last_not_of(" \t") - first + 1);
}

void appendField(std::string& out, std::string_view name, std::string_view value) {
  out.append(name);
  out.append(": ");
  out.append(value);
  out.append("\r\n");
}

std::string_view decimal(std::array<char, 24>& text, std::size_t value) noexcept {
  const auto end = std::to_chars(text.data(), text.data() + text.size(), value).ptr;
  return {text.data(), static_cast<std::size_t>(end - text.data())};
}

} // namespace

bool isServerOwnedHeader(std::string_view name) noexcept {
  static constexpr std::array<std::string_view, 8> kOwned = {
      "content-length", "transfer-encoding",          "connection", "keep-alive", "date", "server",
      "upgrade",        "access-control-allow-origin"};
  for (std::string_view owned : kOwned)
    if (equalsIgnoreCase(owned, name))
      return true;
  return false;
}

std::string httpDate(std::chrono::system_clock::time_point time) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(time);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  std::array<char, 64> text{};
  const std::size_t n = std::strftime(text.data(), text.size(), "%a, %d %b %Y %H:%M:%S GMT", &utc);
  return std::string(text.data(), n);
}

std::string_view currentHttpDate() {
  thread_local std::time_t second = -1;
  thread_local std::string text;
  const auto now = std::chrono::system_clock::now();
  const std::time_t nowSecond = std::chrono::system_clock::to_time_t(now);
  if (nowSecond != second) {
    text = httpDate(now);
    second = nowSecond;
  }
  return text;
}

Response preflightResponse() {
  Response response;
  response.status = 204;
  response.route = "options";
  response.headers = {{"Access-Control-Allow-Methods", std::string(kAllowedMethods)},
                      {"Access-Control-Allow-Headers", "*"},
                      {"Access-Control-Max-Age", "86400"},
                      {"Allow", std::string(kAllowedMethods)}};
  return response;
}

WireResponse toWireResponse(Response response, unsigned version, bool head) {
  if (response.status < 200 || response.status > 599)
    response =
        errorResponse(500, "handler returned invalid status " + std::to_string(response.status));
  WireResponse wire;
  wire.status = static_cast<unsigned>(response.status);
  wire.version = version == 10 ? 10 : 11;
  if (response.preparedFields) {
    wire.sharedFields = std::move(response.preparedFields);
  } else {
    wire.ownFields = prepareFields(response);
  }
  if (head || isBodiless(response.status))
    return wire;
  wire.body = response.sharedBody ? std::move(response.sharedBody)
                                  : std::make_shared<const std::string>(std::move(response.body));
  return wire;
}

void appendHead(std::string& out, const WireResponse& response, bool keepAlive,
                std::string_view date) {
  const unsigned status = response.status;
  const char code[] = {' ', static_cast<char>('0' + status / 100 % 10),
                       static_cast<char>('0' + status / 10 % 10),
                       static_cast<char>('0' + status % 10), ' '};
  out.append(response.version == 10 ? "HTTP/1.0" : "HTTP/1.1");
  out.append(code, sizeof code);
  out.append(toStd(bhttp::obsolete_reason(static_cast<bhttp::status>(status))));
  out.append("\r\n");
  out.append(response.fields());
  appendField(out, "Date", date);
  if (response.version == 10 && keepAlive) {
    appendField(out, "Connection", "keep-alive");
  } else if (response.version != 10 && !keepAlive) {
    appendField(out, "Connection", "close");
  }
  out.append("\r\n");
}

} // namespace strahler::http::detail

namespace strahler::http {

std::string prepareFields(const Response& response) {
  using namespace detail;
  std::string out;
  out.reserve(192);
  for (const auto& [name, value] : response.headers)
    if (!isServerOwnedHeader(name) && isWritableHeader(name, value))
      appendField(out, name, trimmed(value));
  if (response.status >= 500 && !hasHeader(response, "cache-control"))
    appendField(out, "Cache-Control", "no-store");
  appendField(out, "Server", kServerName);
  appendField(out, "Access-Control-Allow-Origin", "*");
  if (!isBodiless(response.status)) {
    std::array<char, 24> text{};
    appendField(
        out, "Content-Length",
        decimal(text, response.sharedBody ? response.sharedBody->size() : response.body.size()));
  }
  return out;
}

} // namespace strahler::http
