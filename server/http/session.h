#pragma once

#include "http_types.h"
#include "net.h"
#include "server_state.h"

#include <boost/beast/core/flat_buffer.hpp>
#include <boost/optional/optional.hpp>

#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>

namespace strahler::http::detail {

/// One HTTP/1.1 connection (Beast advanced_server model): reads request headers one after the
/// other, answers protocol errors itself, hands GET/HEAD to the handler, and writes the
/// responses strictly in request order even when the handler completes them out of order.
/// Reading pauses while maxPipelined responses are owed. All members are used only on the
/// session's strand; the public functions other than closeNow() may be called from any thread.
/// Timeouts use two plain timers instead of beast::tcp_stream's expiry: that one closes the
/// socket when a read-ahead times out, even while a slow handler still owes a response, and its
/// expires_after() asserts when a read and a write are both pending, as they are when pipelining.
class Session : public std::enable_shared_from_this<Session> {
public:
  /// A session for an accepted `socket` whose executor is a strand of the state's io_context.
  Session(std::shared_ptr<ServerState> state, tcp::socket socket);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  /// Registers the connection with the state and starts reading the first request.
  void start();
  /// Graceful shutdown: reads no further request, answers those in flight, then closes.
  void drain();
  /// Closes the connection at once; requests still in flight are dropped.
  void forceClose();
  /// Closes the connection now. Only on the session's strand, or when no I/O thread runs.
  void closeNow() noexcept;

private:
  /// One request's place in the pipeline.
  struct Exchange {
    std::uint64_t sequence = 0; ///< Position in the connection's request order.
    std::string method;         ///< As sent, for the access log.
    std::string target;         ///< As sent, for the access log.
    unsigned version = 11;      ///< 10 or 11.
    bool head = false;          ///< Drop the body when writing.
    bool keepAlive = false;     ///< The connection may stay open after this response.
    std::chrono::steady_clock::time_point start; ///< When the header was complete.
    std::string route = "error";                 ///< Metrics label of the response.
    std::shared_ptr<WireResponse> message;       ///< Set once the response is ready.
  };
  using Duration = std::chrono::steady_clock::duration;

  void doRead();
  void waitForRequest();
  void onRequestStart(ErrorCode ec, std::size_t bytes);
  void readHeader();
  void onHeader(ErrorCode ec, std::size_t bytes);
  void onReadFailed(const ErrorCode& ec);
  bool stopReadingIfClosing();

  void dispatch();
  void answerParseError(const ErrorCode& ec);
  Exchange& enqueue(std::string method, std::string target, unsigned version, bool head,
                    bool keepAlive);
  void callHandler(std::uint64_t sequence, const Request& request);
  void postAnswer(std::uint64_t sequence, Response response);
  void answer(std::uint64_t sequence, Response response);

  void maybeWrite();
  void onWrite(ErrorCode ec);
  void record(const Exchange& exchange, bool sent) noexcept;
  void linger();
  void discard();
  void closeIfIdle();
  void onDrain();

  void armReadTimer(Duration timeout);
  void onReadTimer(ErrorCode ec, std::uint64_t generation, Duration timeout);
  void cancelReadTimer() noexcept;
  void armWriteTimer();
  void cancelWriteTimer() noexcept;

  std::shared_ptr<ServerState> state_;
  const ServerOptions& options_;
  tcp::socket socket_;
  const tcp::socket::executor_type executor_; ///< The strand; copied so any thread may post.
  net::steady_timer readTimer_;
  net::steady_timer writeTimer_;
  beast::flat_buffer buffer_;
  boost::optional<RequestParser> parser_;
  std::deque<Exchange> queue_; ///< Requests whose responses are owed, in order.
  std::uint64_t nextSequence_ = 0;
  std::uint64_t readGeneration_ = 0;  ///< Tells a stale read timeout from the current one.
  std::uint64_t writeGeneration_ = 0; ///< Tells a stale write timeout from the current one.
  std::size_t discarded_ = 0;         ///< Bytes thrown away while lingering.
  bool firstRequest_ = true;
  bool reading_ = false;   ///< A read (idle wait, header or discard) is pending.
  bool writing_ = false;   ///< A write is pending.
  bool closing_ = false;   ///< Read no further requests; close once the queue is empty.
  bool lingering_ = false; ///< Final response sent, send side shut down; waiting for EOF.
  bool closed_ = false;
};

} // namespace strahler::http::detail
