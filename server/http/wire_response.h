#pragma once

#include "http_types.h"
#include "net.h"

#include <chrono>
#include <memory>
#include <string>
#include <string_view>

namespace strahler::http::detail {

/// Value of the Server header on every response.
inline constexpr std::string_view kServerName = "strahler";
/// Methods the server answers, for Allow and Access-Control-Allow-Methods.
inline constexpr std::string_view kAllowedMethods = "GET, HEAD, OPTIONS";

/// True for headers the server writes itself (Date, Server, Content-Length, Connection, ...):
/// a handler's copies are dropped. `name` is compared case-insensitively.
bool isServerOwnedHeader(std::string_view name) noexcept;

/// RFC 9110 IMF-fixdate of `time`, e.g. "Sun, 06 Nov 1994 08:49:37 GMT".
std::string httpDate(std::chrono::system_clock::time_point time);

/// The 204 answer to any OPTIONS request (a CORS preflight): allow every origin and header.
Response preflightResponse();

/// `response` as written for a request of HTTP `version` (10 or 11): the handler's headers
/// (server-owned and malformed ones dropped) plus Date, Server, Access-Control-Allow-Origin: *,
/// Content-Length (not on 204/304), and Cache-Control: no-store on a 5xx that has none. For
/// `head` the body is dropped and Content-Length still counts it. A status outside 200..599
/// becomes a 500. The Connection header is left to the session.
std::shared_ptr<WireResponse> toWireResponse(Response response, unsigned version, bool head);

} // namespace strahler::http::detail
