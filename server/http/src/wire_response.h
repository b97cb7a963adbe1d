#pragma once

#include "strahler/http/http_types.h"

#include <chrono>
#include <cstddef>
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

/// httpDate() of now, formatted at most once per second per thread. The view stays valid until
/// the calling thread calls this again.
std::string_view currentHttpDate();

/// The 204 answer to any OPTIONS request (a CORS preflight): allow every origin and header.
Response preflightResponse();

/// A response ready for the wire except for what depends on the moment and the connection
/// (Date, Connection), which appendHead() adds when it is written.
struct WireResponse {
  unsigned status = 200; ///< 200..599.
  unsigned version = 11; ///< 10 or 11.
  std::string ownFields; ///< Serialised header fields (prepareFields()), unless shared.
  std::shared_ptr<const std::string> sharedFields; ///< Prepared fields, e.g. a cached tile's.
  std::shared_ptr<const std::string> body;         ///< Null when none is sent (HEAD, 204, 304).

  /// The serialised header fields.
  const std::string& fields() const noexcept { return sharedFields ? *sharedFields : ownFields; }
  /// Bytes of body sent.
  std::size_t bodyBytes() const noexcept { return body ? body->size() : 0; }
};

/// `response` as written for a request of HTTP `version` (10 or 11): the fields of
/// prepareFields() (or the response's prepared ones). For `head` the body is dropped and
/// Content-Length still counts it. A status outside 200..599 becomes a 500.
WireResponse toWireResponse(Response response, unsigned version, bool head);

/// Appends the header block of `response` to `out`: status line, fields, Date: `date`, the
/// Connection header that `keepAlive` needs for the response's version, and the empty line.
void appendHead(std::string& out, const WireResponse& response, bool keepAlive,
                std::string_view date);

} // namespace strahler::http::detail
