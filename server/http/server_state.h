#pragma once

#include "http_server.h"
#include "http_types.h"
#include "net.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace strahler::http::detail {

class Session;

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

  /// Counts `session` as an open connection until remove() or its destruction.
  void add(const std::shared_ptr<Session>& session);
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
  mutable std::mutex mutex_; ///< Guards sessions_ and gateOpen_.
  std::condition_variable idle_;
  std::unordered_map<const Session*, std::weak_ptr<Session>> sessions_;
  bool gateOpen_ = true;
};

} // namespace strahler::http::detail
