#pragma once

#include "net.h"

#include "strahler/http/http_server.h"
#include "strahler/http/http_types.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace strahler::http::detail {

class Session;

/// The key a client's connections are counted under: its IPv4 address (IPv4-mapped IPv6
/// too), or the /64 prefix of its IPv6 address (one host usually holds a whole /64).
std::string clientKey(const net::ip::address& address);

/// What the listener and every session share: options, callbacks, the event loops (one
/// io_context per I/O thread, so that a connection's handlers run on one thread and need no
/// strand), the registry of open connections, and the gate through which worker threads hand
/// responses back. Sessions
/// hold it by shared_ptr, so a `done` callback kept by a worker after Server::stop() still
/// refers to live objects; once the gate is closed such late completions are dropped.
class ServerState {
public:
  ServerState(ServerOptions options, Handler handler, RequestObserver observer);

  /// The options the server was started with.
  const ServerOptions& options() const noexcept { return options_; }
  /// The event loops, one per I/O thread; the first also runs the listener.
  const std::vector<std::unique_ptr<net::io_context>>& ioContexts() const noexcept {
    return ioContexts_;
  }
  /// The event loop for the next connection (round robin).
  net::io_context& nextIoContext() noexcept;
  /// The handler for valid GET/HEAD requests.
  const Handler& handler() const noexcept { return handler_; }

  /// What admit() decided about a new connection.
  enum class Admission {
    kAccept,       ///< Start a session (perhaps after shedding an idle one).
    kRefuseClient, ///< The client holds maxConnectionsPerClient busy connections.
    kRefuseFull,   ///< maxConnections busy connections are open.
  };
  /// Decides on a new connection from `client` (clientKey()). At a cap it sheds the oldest
  /// sheddable connection (Session::sheddableSince()) of the client, or of anyone at the
  /// global cap, which then no longer counts, and accepts; refuses when none is sheddable.
  /// Only from the listener, which calls add() right after kAccept.
  Admission admit(const std::string& client);
  /// Counts `session` of `client` as an open connection until remove() or its destruction.
  void add(const std::shared_ptr<Session>& session, const std::string& client);
  /// Forgets `session` (idempotent) and wakes waitUntilIdle().
  void remove(const Session* session) noexcept;
  /// The sessions still open.
  std::vector<std::shared_ptr<Session>> sessions() const;
  /// Number of open connections.
  std::size_t connections() const noexcept { return connections_.load(); }
  /// Waits until no connection is open or `deadline` passes; true when none is open.
  bool waitUntilIdle(std::chrono::steady_clock::time_point deadline);

  /// Marks the server as shutting down: responses close their connections.
  void startDraining() noexcept { draining_.store(true); }
  /// True once startDraining() was called.
  bool draining() const noexcept { return draining_.load(); }

  /// Posts `work` to `executor` unless the gate is closed (then drops it); any thread.
  template <class Executor, class Work> void postThroughGate(const Executor& executor, Work work) {
    std::lock_guard lock(mutex_);
    if (gateOpen_)
      net::post(executor, std::move(work));
  }
  /// Closes the gate: later postThroughGate() calls do nothing. Called once the I/O threads
  /// have been joined, before the io_context is drained for the last time.
  void closeGate() noexcept;

  /// Reports a finished request to the access log and the observer; never throws.
  void record(std::string_view method, std::string_view target, const std::string& route,
              int status, std::size_t bytes, double ms) noexcept;

private:
  ServerOptions options_;
  Handler handler_;
  RequestObserver observer_;
  std::vector<std::unique_ptr<net::io_context>> ioContexts_;
  std::atomic<std::size_t> nextIoContext_{0};
  std::atomic<std::size_t> connections_{0};
  std::atomic<bool> draining_{false};
  mutable std::mutex mutex_; ///< Guards sessions_, clients_, counted_ and gateOpen_.
  std::condition_variable idle_;
  /// An open connection as the registry keeps it.
  struct Registered {
    std::weak_ptr<Session> session;
    std::string client;
    bool shed = false; ///< Being shed: no longer counted against the caps.
  };
  /// Under mutex_: marks the oldest sheddable connection (of `client` unless null) as shed
  /// and returns it (null when none is sheddable or it is already being destroyed).
  std::shared_ptr<Session> pickVictim(const std::string* client, bool& found);
  void uncount(const std::string& client) noexcept;

  std::unordered_map<const Session*, Registered> sessions_;
  std::unordered_map<std::string, std::size_t> clients_; ///< Counted connections per client.
  std::size_t counted_ = 0;                              ///< Open connections not being shed.
  bool gateOpen_ = true;
};

} // namespace strahler::http::detail
