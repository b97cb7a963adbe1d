#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace strahler::http {

/// A request as the handler sees it: method and target already validated by the server
/// (GET or HEAD only; HEAD arrives as "GET" with `head` set), headers lower-cased.
struct Request {
  std::string method; ///< "GET".
  bool head = false;  ///< True when the client sent HEAD: the server drops the body.
  std::string target; ///< Raw request target, e.g. "/worlds/default/tiles/3/4/2.png?size=512".
  std::vector<std::pair<std::string, std::string>> headers; ///< Lower-cased names.
  /// The address the client connected to, as a URL authority ("127.0.0.1:8080",
  /// "[::1]:8080"): the socket's own local endpoint, never taken from the request.
  std::string localAddress;
  /// True when the peer is one of ServerOptions::trustedProxies: its X-Forwarded-Proto and
  /// X-Forwarded-Host describe the client's view of the URL and may be used.
  bool fromTrustedProxy = false;
  /// Becomes true once the client has closed or reset its connection (or the server closed
  /// it): the response can no longer be delivered, so a handler may skip queued work for it.
  /// Null when there is no connection to watch.
  std::shared_ptr<const std::atomic<bool>> clientGone;

  /// Value of header `name` (lower-case), or empty.
  std::string header(const std::string& name) const {
    for (const auto& [k, v] : headers)
      if (k == name)
        return v;
    return {};
  }
};

/// A response; the server adds Date, Server, Content-Length, CORS and connection headers.
struct Response {
  int status = 200;
  std::vector<std::pair<std::string, std::string>> headers; ///< e.g. Content-Type, ETag.
  std::string body;
  /// When set, sent instead of `body` without copying (e.g. a cached tile's bytes).
  std::shared_ptr<const std::string> sharedBody;
  /// When set, sent instead of `headers`: fields from prepareFields() of a response with this
  /// status and body size (e.g. kept with a cached tile), so nothing is formatted per request.
  std::shared_ptr<const std::string> preparedFields;
  std::string route = "other"; ///< Label for metrics ("tile", "tilejson", "health", ...).
  bool close = false;          ///< Close the connection after this response (every 400 does).
};

/// Builds a JSON error response {"error": message} with `status`, Content-Type
/// application/json, route "error", and Cache-Control: no-store when status >= 500. The message
/// is JSON-escaped (invalid UTF-8 becomes U+FFFD), so it may quote client input.
Response errorResponse(int status, const std::string& message);

/// The header fields the server writes for `response`, serialised ("Name: value\r\n" each):
/// the handler's (server-owned and malformed ones dropped, values trimmed), then Cache-Control
/// on a 5xx without one, Server, Access-Control-Allow-Origin and Content-Length (not on
/// 204/304). Date and Connection are added per request. For Response::preparedFields; valid
/// only for responses with the same status (200..599) and body size.
std::string prepareFields(const Response& response);

/// Asynchronous request handler: call `done` exactly once, from any thread, inline or later.
/// A handler that never calls it leaves its connection waiting (Server::stop() gives up on it
/// after the drain time); calling it twice is a bug that asserts in debug builds and is ignored
/// otherwise. An exception thrown by the handler becomes a 500 (unless `done` was called).
using Handler = std::function<void(const Request&, std::function<void(Response)> done)>;

/// Called once per finished request, on an I/O thread, after the response was written: route
/// label ("error" for the server's own error answers, "options" for preflights), status, body
/// bytes sent (0 for HEAD), milliseconds from the complete request header to the written
/// response. Also called with ("error", 503, ...) for connections refused at the cap.
using RequestObserver =
    std::function<void(const std::string& route, int status, std::size_t bytes, double ms)>;

} // namespace strahler::http
