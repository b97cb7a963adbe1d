#pragma once

#include "strahler/base/result.h"
#include "strahler/http/http_types.h"
#include "strahler/http/trusted_proxies.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

namespace strahler::http {

/// Limits and timeouts of the HTTP server; every one is enforced.
struct ServerOptions {
  std::string host = "127.0.0.1";
  std::uint16_t port = 8080; ///< 0: an ephemeral port (see Server::port()).
  int ioThreads = 2;         ///< Threads running the Asio event loop.
  /// At the cap a new connection sheds the oldest idle or header-incomplete one (see
  /// maxConnectionsPerClient); when none is, it gets a 503 (Retry-After: 1) and is closed.
  std::size_t maxConnections = 1024;
  /// Connections one client address (IPv6: one /64) may hold; beyond it a new one sheds that
  /// client's oldest idle or header-incomplete connection, or gets a 503. 0: no limit (behind
  /// a proxy, whose address every connection has).
  std::size_t maxConnectionsPerClient = 64;
  std::size_t maxTargetBytes = 2048; ///< Longer request targets get 414.
  std::size_t maxHeaderBytes = 8192; ///< Larger header blocks get 431.
  std::size_t maxPipelined = 16;     ///< Responses queued per connection before reading pauses.
  /// To receive a complete request header; then 408 and close.
  std::chrono::milliseconds headerTimeout{10000};
  std::chrono::milliseconds idleTimeout{30000};  ///< Keep-alive idle time between requests.
  std::chrono::milliseconds writeTimeout{30000}; ///< To send one response.
  bool accessLog = true;                         ///< One line per request on stdout.
  /// Peers whose X-Forwarded-* headers reach the handler as Request::fromTrustedProxy.
  TrustedProxies trustedProxies;
};

/// An HTTP/1.1 server (Boost.Beast) on its own I/O threads. Protocol rules live here:
/// GET/HEAD (HEAD = GET without body), OPTIONS preflight (204), other methods 405 with
/// Allow, 400 for malformed requests, a body on GET, or any Transfer-Encoding other than
/// "chunked" (and the connection is closed), 414 and 431 for oversize targets and headers,
/// CORS "*" on every response, keep-alive with in-order pipelining, timeouts so that slow
/// clients cannot pin connections (a header not complete within headerTimeout gets 408), a
/// per-client connection limit and shedding of idle connections at the cap so that one client
/// cannot take them all, back-off when accept fails (EMFILE). Everything else is the
/// handler's. Beast stays inside server/http.
/// Decisions where HTTP leaves a choice: a well-formed "HTTP/x.y" other than 1.0 and 1.1 gets
/// 505; lines ending in a bare LF get 400; the target must be origin-form ("/..."), so
/// absolute-form and "*" get 400 on GET/HEAD; every 400 closes the connection (the handler's
/// too, e.g. for a bad path), as do 431 and 505, while 405 and 414 keep it open unless a body
/// was announced. The answer to HEAD never
/// carries a body, not even an error's.
class Server {
public:
  /// A server that will call `handler` for every valid GET/HEAD request.
  Server(ServerOptions options, Handler handler, RequestObserver observer = {});
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  /// Binds, listens and starts the I/O threads. kIoError when the address cannot be bound.
  base::Status start();
  /// The bound port (useful with port 0).
  std::uint16_t port() const noexcept;
  /// Stops accepting, lets in-flight requests finish for up to `drain` (idle connections close
  /// at once, the last owed response carries Connection: close), then closes every connection
  /// and joins the I/O threads; returns within about drain + 0.3 s. Safe to call twice; must
  /// not be called from the handler or an observer (an I/O thread).
  void stop(std::chrono::milliseconds drain = std::chrono::milliseconds(4000));
  /// Number of open connections.
  std::size_t connections() const noexcept;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace strahler::http
