#include "wire_response.h"

#include <array>
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

std::shared_ptr<WireResponse> toWireResponse(Response response, unsigned version, bool head) {
  if (response.status < 200 || response.status > 599)
    response =
        errorResponse(500, "handler returned invalid status " + std::to_string(response.status));
  auto wire = std::make_shared<WireResponse>();
  wire->version(version);
  wire->result(static_cast<unsigned>(response.status));
  for (const auto& [name, value] : response.headers)
    if (!isServerOwnedHeader(name) && isWritableHeader(name, value))
      wire->insert(toBeast(name), toBeast(value));
  if (response.status >= 500 && !hasHeader(response, "cache-control"))
    wire->set(bhttp::field::cache_control, "no-store");
  wire->set(bhttp::field::date, httpDate(std::chrono::system_clock::now()));
  wire->set(bhttp::field::server, toBeast(kServerName));
  wire->set(bhttp::field::access_control_allow_origin, "*");
  if (isBodiless(response.status))
    return wire;
  std::shared_ptr<const std::string> body =
      response.sharedBody ? std::move(response.sharedBody)
                          : std::make_shared<const std::string>(std::move(response.body));
  wire->set(bhttp::field::content_length, std::to_string(body->size()));
  if (!head)
    wire->body() = std::move(body);
  return wire;
}

} // namespace strahler::http::detail
