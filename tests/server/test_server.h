#pragma once

#include "strahler/http/http_server.h"
#include "strahler/http/http_types.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace strahler::http::test {

/// Short timeouts and no access log: every test finishes in well under a second or two.
ServerOptions testOptions();

/// One RequestObserver call.
struct Observation {
  std::string route;
  int status = 0;
  std::size_t bytes = 0;
};

/// A started Server with a small handler that exercises the server:
///   /slow...     answered with the target after 200 ms from a worker thread
///   /throw       throws std::runtime_error
///   /big, /huge  1 MiB and 16 MiB bodies
///   /close       asks the server to close the connection (Response::close)
///   /hang        never answered until releaseHung() is called
///   /status/N    status N with a text body
///   /evil        a header with CR LF injected, which the server must drop
///   /twice       calls `done` twice (a handler bug)
///   /x-test      echoes the request's X-Test header (looked up lower-case)
///   /fields/N    status N with padded, server-owned and malformed headers; with "?prepared"
///                the same fields sent only through Response::preparedFields
///   anything else: 200 text/plain echoing the target, with X-Head: 1 for HEAD requests.
class TestServer {
public:
  explicit TestServer(ServerOptions options = testOptions());
  ~TestServer();
  TestServer(const TestServer&) = delete;
  TestServer& operator=(const TestServer&) = delete;

  /// The listening port.
  std::uint16_t port() const { return server_.port(); }
  /// The server under test.
  Server& server() { return server_; }
  /// Every observer call so far.
  std::vector<Observation> observations() const;
  /// Number of handler calls that reached /hang.
  int hungCount() const { return hung_.load(); }
  /// Number of /hang requests whose Request::clientGone is set now.
  int hungClientsGone() const;
  /// Number of handler calls so far.
  int handlerCalls() const { return calls_.load(); }
  /// The most /slow requests that were being handled at one time so far.
  int peakSlowInFlight() const { return slowPeak_.load(); }
  /// Calls the `done` of every /hang request with 200 (the server may be stopped by then).
  void releaseHung();

private:
  void handle(const Request& request, std::function<void(Response)> done);
  void later(std::function<void()> work);

  mutable std::mutex mutex_;
  std::vector<std::thread> workers_;
  std::vector<Observation> observations_;
  std::vector<std::function<void(Response)>> hungDone_;
  std::vector<std::shared_ptr<const std::atomic<bool>>> hungGone_;
  std::atomic<int> hung_{0};
  std::atomic<int> calls_{0};
  std::atomic<int> slowInFlight_{0};
  std::atomic<int> slowPeak_{0};
  Server server_;
};

/// Polls `condition` every 5 ms until it holds or `timeout` passes; true when it held.
template <class Condition> bool eventually(Condition condition, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > deadline)
      return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

/// Milliseconds since `start`.
double msSince(std::chrono::steady_clock::time_point start);

} // namespace strahler::http::test
