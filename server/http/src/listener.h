#pragma once

#include "net.h"
#include "server_state.h"

#include "strahler/base/result.h"

#include <chrono>
#include <cstdint>
#include <memory>

namespace strahler::http::detail {

/// Pause before accepting again after accept() failed (EMFILE, ENFILE, ENOBUFS, ...): the
/// listening socket stays readable, so retrying at once would spin.
inline constexpr std::chrono::milliseconds kAcceptRetryDelay{50};

/// Accepts connections and starts a Session for each. At maxConnections, or at
/// maxConnectionsPerClient for the client's address, the oldest idle or header-incomplete
/// connection (the client's own at its limit) is shed to make room (ServerState::admit()); when
/// none is, and while the server drains, a connection gets a 503 with Retry-After: 1 and is
/// closed at once. Runs on the first I/O thread; connections go to the I/O threads in turn.
class Listener : public std::enable_shared_from_this<Listener> {
public:
  /// A listener whose sessions share `state`.
  explicit Listener(std::shared_ptr<ServerState> state);

  /// Opens, binds and listens on `endpoint`; kIoError with the reason when that fails.
  base::Status open(const tcp::endpoint& endpoint);
  /// The bound port (after open()).
  std::uint16_t port() const noexcept { return port_; }
  /// Starts the accept loop.
  void run();
  /// Stops accepting (asynchronously, on the listener's thread).
  void stop();
  /// Closes the acceptor now. Only when no I/O thread runs.
  void closeNow() noexcept;

private:
  void doAccept();
  void onAccept(ErrorCode ec, Socket socket);
  void onAcceptError(const ErrorCode& ec);
  void refuse(Socket socket, const char* reason) noexcept;

  std::shared_ptr<ServerState> state_;
  net::basic_socket_acceptor<tcp, Executor> acceptor_;
  Timer retryTimer_;
  std::uint16_t port_ = 0;
  bool stopped_ = false;
  bool failing_ = false; ///< accept() failed last time; the failure was reported once.
};

} // namespace strahler::http::detail
