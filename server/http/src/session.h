#pragma once

#include "net.h"
#include "server_state.h"
#include "wire_response.h"

#include "strahler/http/http_types.h"

#include <boost/beast/core/flat_buffer.hpp>
#include <boost/optional/optional.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace strahler::http::detail {

/// One HTTP/1.1 connection (Beast advanced_server model): reads request headers one after the
/// other, answers protocol errors itself, hands GET/HEAD to the handler, and writes the
/// responses strictly in request order even when the handler completes them out of order.
/// Reading pauses while maxPipelined responses are owed. All members are used only on the
/// session's I/O thread (its event loop has exactly one); the public functions other than
/// closeNow() may be called from any thread. A handler that answers at once, on that thread,
/// is answered without a round trip through the event loop.
/// Timeouts use two plain timers instead of beast::tcp_stream's expiry: that one closes the
/// socket when a read-ahead times out, even while a slow handler still owes a response, and its
/// expires_after() asserts when a read and a write are both pending, as they are when pipelining.
/// The timers are lazy: a deadline that moves later is only recorded, and a timer that wakes
/// before its deadline sleeps again, so a busy connection does not touch them per request.
/// State: the connection's Phase, the pending Read, and beside them the pending write
/// (writing_: a response goes out while the next request is read) and the owed responses.
class Session : public std::enable_shared_from_this<Session> {
public:
  /// Steady-clock ticks (since its epoch).
  using Ticks = std::chrono::steady_clock::rep;

  /// A session for an accepted `socket` of `client` (clientKey()), on the I/O thread that runs
  /// its executor.
  Session(std::shared_ptr<ServerState> state, Socket socket, std::string client);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  /// Registers the connection with the state and starts reading the first request.
  void start();
  /// Graceful shutdown: reads no further request, answers those in flight, then closes.
  void drain();
  /// Closes the connection at once; requests still in flight are dropped.
  void forceClose();
  /// Closes the connection now. Only on the session's thread, or when no I/O thread runs.
  void closeNow() noexcept;
  /// Makes room for a new connection: an idle connection closes at once, one with a header
  /// begun gets 503 (Retry-After: 1) and closes, one that owes responses drains.
  void shed();
  /// When the connection became sheddable (waiting for a request or its header, nothing owed),
  /// or 0 while it is not. Any thread.
  Ticks sheddableSince() const noexcept { return sheddableSince_.load(std::memory_order_relaxed); }

private:
  using Clock = std::chrono::steady_clock;
  using Duration = Clock::duration;

  /// The connection's life. It only moves forward: kOpen → kClosing → kLingering → kClosed, any
  /// step may be skipped (closeNow() goes to kClosed from anywhere).
  enum class Phase {
    kOpen,      ///< Reads requests and answers them.
    kClosing,   ///< Reads no further request; closes once the owed responses are written.
    kLingering, ///< Final response sent, send side shut down; reading until EOF (linger()).
    kClosed,    ///< Socket closed; completions that still arrive do nothing.
  };

  /// The read pending on the socket (at most one), which says what its completion and a read
  /// timeout mean.
  enum class Read {
    kNone,    ///< No read pending.
    kIdle,    ///< Waiting for the first bytes of the next keep-alive request (idle timeout).
    kHeader,  ///< Reading a request header (header timeout: 408).
    kDiscard, ///< Lingering: reading and dropping what the client still sends.
  };

  /// One request's place in the pipeline.
  struct Exchange {
    std::uint64_t sequence = 0;          ///< Position in the connection's request order.
    std::string method;                  ///< As sent, for the access log (empty when it is off).
    std::string target;                  ///< As sent, for the access log (empty when it is off).
    unsigned version = 11;               ///< 10 or 11.
    bool head = false;                   ///< Drop the body when writing.
    bool keepAlive = false;              ///< The connection may stay open after this response.
    Clock::time_point start;             ///< When the header was complete.
    std::string route = "error";         ///< Metrics label of the response.
    std::optional<WireResponse> message; ///< Set once the response is ready.
  };

  /// A lazily re-armed timeout (see the class comment).
  struct Deadline {
    explicit Deadline(const Executor& executor) : timer(executor) {}
    Timer timer;
    Duration timeout{};           ///< Of the last arm().
    Clock::time_point at;         ///< Expiry, while armed.
    Clock::time_point wakeAt;     ///< End of the pending wait, while waiting.
    std::uint64_t generation = 0; ///< Of the pending wait; older wakes are ignored.
    bool armed = false;
    bool waiting = false;
  };

  void doRead();
  void waitForRequest();
  void onRequestStart(ErrorCode ec, std::size_t bytes);
  void parseBuffered();
  void readMore();
  void onMoreRead(ErrorCode ec, std::size_t bytes);
  void onHeader();
  void onReadFailed(const ErrorCode& ec);
  bool stopReadingIfClosing();

  void dispatch();
  void answerParseError(const ErrorCode& ec);
  Exchange& enqueue(std::string_view method, std::string_view target, unsigned version, bool head,
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
  /// kOpen → kClosing (later phases stay).
  void beginClosing() noexcept;
  /// True until the first request header is complete (no request has been queued yet).
  bool firstRequest() const noexcept { return nextSequence_ == 0; }
  void onDrain();
  void onShed();
  void answerAndClose(int status, const std::string& message);
  void updateSheddable() noexcept;

  void arm(Deadline& deadline, Duration timeout);
  void wait(Deadline& deadline);
  void onWake(Deadline& deadline, std::uint64_t generation);
  void onReadTimeout();
  static void disarm(Deadline& deadline) noexcept { deadline.armed = false; }
  static void cancel(Deadline& deadline) noexcept;

  std::shared_ptr<ServerState> state_;
  const ServerOptions& options_;
  Socket socket_;
  const Executor executor_; ///< The I/O thread's; copied so any thread may post.
  Deadline readDeadline_;
  Deadline writeDeadline_;
  beast::flat_buffer buffer_;
  boost::optional<RequestParser> parser_;
  std::deque<Exchange> queue_;    ///< Requests whose responses are owed, in order.
  std::string localAddress_;      ///< Request::localAddress of every request on this connection.
  bool fromTrustedProxy_ = false; ///< Request::fromTrustedProxy of every request on it.
  std::string client_;            ///< The clientKey() of the peer's address.
  /// Request::clientGone of every request on this connection; set by closeNow() and when the
  /// peer ends or resets the connection while responses are owed.
  std::shared_ptr<std::atomic<bool>> clientGone_ = std::make_shared<std::atomic<bool>>(false);
  std::atomic<Ticks> sheddableSince_{0};
  std::string head_; ///< Header block of the response being written.
  std::uint64_t nextSequence_ = 0;
  std::size_t discarded_ = 0; ///< Bytes thrown away while lingering.
  Phase phase_ = Phase::kOpen;
  Read read_ = Read::kNone;
  bool writing_ = false; ///< A write is pending (independent of the read: pipelining).
  bool shed_ = false;    ///< Closed to make room for another connection (short linger).
};

} // namespace strahler::http::detail
