#include "session.h"

#include "request_rules.h"
#include "wire_response.h"

#include <boost/asio/dispatch.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core/bind_handler.hpp>
#include <boost/beast/core/read_size.hpp>
#include <boost/beast/http/error.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <cstdio>
#include <exception>
#include <limits>

namespace strahler::http::detail {
namespace {

using Clock = std::chrono::steady_clock;

/// Bytes asked for while waiting for the next keep-alive request, and per discard read.
constexpr std::size_t kReadChunkBytes = 4096;
/// Most bytes asked for per read while a header is incomplete (as Beast's read does).
constexpr std::size_t kMaxHeaderReadBytes = 65536;
/// After a closing response the server drains what the client still sends (so that the
/// kernel does not answer it with a reset that could destroy the response), for at most this
/// long and this many bytes; shorter while the server drains or the connection was shed (its
/// descriptor is wanted).
constexpr Clock::duration kLingerTimeout = std::chrono::milliseconds(500);
constexpr Clock::duration kDrainingLingerTimeout = std::chrono::milliseconds(100);
constexpr std::size_t kMaxLingerBytes = 64 * 1024;

/// `endpoint` as a URL authority: "a.b.c.d:port" (IPv4-mapped IPv6 too) or "[v6]:port".
std::string urlAuthority(const tcp::endpoint& endpoint) {
  const net::ip::address address = endpoint.address();
  std::string host;
  if (address.is_v6() && address.to_v6().is_v4_mapped()) {
    host = net::ip::make_address_v4(net::ip::v4_mapped, address.to_v6()).to_string();
  } else if (address.is_v6()) {
    net::ip::address_v6 v6 = address.to_v6();
    v6.scope_id(0); // a zone id is local to this host: of no use in a URL
    host = "[" + v6.to_string() + "]";
  } else {
    host = address.to_string();
  }
  return host + ":" + std::to_string(endpoint.port());
}

} // namespace

Session::Session(std::shared_ptr<ServerState> state, Socket socket, std::string client)
    : state_(std::move(state)), options_(state_->options()), socket_(std::move(socket)),
      executor_(socket_.get_executor()), readDeadline_(executor_), writeDeadline_(executor_),
      client_(std::move(client)) {}

Session::~Session() {
  state_->remove(this);
}

void Session::start() {
  ErrorCode ignored;
  // Responses are written whole (one gather write each); Nagle would only delay pipelined ones.
  socket_.set_option(tcp::no_delay(true), ignored);
  localAddress_ = urlAuthority(socket_.local_endpoint(ignored));
  if (!options_.trustedProxies.empty()) {
    const net::ip::address peer = socket_.remote_endpoint(ignored).address();
    fromTrustedProxy_ =
        !ignored &&
        options_.trustedProxies.contains(
            peer.is_v4() ? net::ip::make_address_v6(net::ip::v4_mapped, peer.to_v4()).to_bytes()
                         : peer.to_v6().to_bytes());
  }
  state_->add(shared_from_this(), client_);
  net::dispatch(executor_, [self = shared_from_this()] { self->doRead(); });
}

void Session::drain() {
  net::post(executor_, [self = shared_from_this()] { self->onDrain(); });
}

void Session::forceClose() {
  net::post(executor_, [self = shared_from_this()] { self->closeNow(); });
}

void Session::shed() {
  net::post(executor_, [self = shared_from_this()] { self->onShed(); });
}

void Session::closeNow() noexcept {
  if (phase_ == Phase::kClosed)
    return;
  phase_ = Phase::kClosed;
  clientGone_->store(true, std::memory_order_relaxed);
  ErrorCode ignored;
  socket_.shutdown(tcp::socket::shutdown_both, ignored);
  socket_.close(ignored);
  cancel(readDeadline_);
  cancel(writeDeadline_);
  queue_.clear();
  updateSheddable();
  state_->remove(this);
}

void Session::beginClosing() noexcept {
  if (phase_ == Phase::kOpen)
    phase_ = Phase::kClosing;
}

// ---- reading -------------------------------------------------------------------------------

void Session::doRead() {
  if (phase_ != Phase::kOpen || read_ != Read::kNone || queue_.size() >= options_.maxPipelined)
    return;
  parser_.emplace();
  parser_->header_limit(static_cast<std::uint32_t>(
      std::min<std::size_t>(options_.maxHeaderBytes, std::numeric_limits<std::uint32_t>::max())));
  // No body is ever read, so the body limit is only a formality: checkRequest() answers any
  // announced body with the right status. (boost::none would fail even Content-Length: 0.)
  parser_->body_limit(std::numeric_limits<std::uint64_t>::max());
  if (buffer_.size() == 0 && !firstRequest())
    return waitForRequest();
  read_ = Read::kHeader;
  arm(readDeadline_, options_.headerTimeout);
  parseBuffered();
  updateSheddable();
}

void Session::waitForRequest() {
  read_ = Read::kIdle;
  arm(readDeadline_, options_.idleTimeout);
  socket_.async_read_some(buffer_.prepare(kReadChunkBytes),
                          beast::bind_front_handler(&Session::onRequestStart, shared_from_this()));
  updateSheddable();
}

void Session::onRequestStart(ErrorCode ec, std::size_t bytes) {
  if (ec)
    return onReadFailed(ec);
  buffer_.commit(bytes);
  if (stopReadingIfClosing())
    return;
  read_ = Read::kHeader;
  arm(readDeadline_, options_.headerTimeout);
  parseBuffered();
}

/// Parses the buffered bytes (pipelined requests are often all there) and reads more only while
/// the header is incomplete: the steps of Beast's async_read_header, without its round trips
/// through the event loop.
void Session::parseBuffered() {
  if (buffer_.size() > 0) {
    ErrorCode ec;
    buffer_.consume(parser_->put(buffer_.data(), ec));
    if (ec && ec != bhttp::error::need_more)
      return onReadFailed(ec);
    if (!ec && parser_->is_header_done())
      return onHeader();
  }
  readMore();
}

void Session::readMore() {
  const std::size_t size = beast::read_size(buffer_, kMaxHeaderReadBytes);
  if (size == 0)
    return onReadFailed(bhttp::error::buffer_overflow);
  socket_.async_read_some(buffer_.prepare(size),
                          beast::bind_front_handler(&Session::onMoreRead, shared_from_this()));
}

void Session::onMoreRead(ErrorCode ec, std::size_t bytes) {
  buffer_.commit(bytes);
  if (ec == net::error::eof) // what the parser's put_eof() says of an unfinished header
    ec = parser_->got_some() ? bhttp::error::partial_message : bhttp::error::end_of_stream;
  if (ec)
    return onReadFailed(ec);
  if (stopReadingIfClosing())
    return;
  parseBuffered();
}

void Session::onHeader() {
  read_ = Read::kNone;
  disarm(readDeadline_);
  dispatch();
  doRead();
  updateSheddable();
}

/// A read completed after the session decided to stop reading (drain, close, linger): the
/// request is not answered.
bool Session::stopReadingIfClosing() {
  if (phase_ == Phase::kOpen)
    return false;
  read_ = Read::kNone;
  disarm(readDeadline_);
  if (phase_ == Phase::kLingering) {
    closeNow();
  } else {
    closeIfIdle();
  }
  return true;
}

void Session::onReadFailed(const ErrorCode& ec) {
  read_ = Read::kNone;
  disarm(readDeadline_);
  if (phase_ == Phase::kClosed)
    return;
  if (phase_ != Phase::kLingering && isParseError(ec))
    return answerParseError(ec);
  // The peer closed or reset the connection, or it timed out: answer what is owed, then close.
  // A peer that closed is most likely gone (a browser cancelling tile requests closes the
  // connection): work queued for it may be skipped. Only a client that half-closes and still
  // reads loses by this (it gets 503), as with nginx's default for proxied requests.
  beginClosing();
  if (!queue_.empty())
    clientGone_->store(true, std::memory_order_relaxed);
  if (phase_ == Phase::kLingering)
    return closeNow();
  closeIfIdle();
}

// ---- answering -----------------------------------------------------------------------------

void Session::dispatch() {
  const auto& header = parser_->get();
  Verdict verdict = checkRequest(*parser_, options_);
  const bool head = header.method() == bhttp::verb::head;
  const Exchange& exchange = enqueue(toStd(header.method_string()), toStd(header.target()),
                                     header.version(), head, header.keep_alive() && !verdict.close);
  if (!exchange.keepAlive)
    beginClosing();
  if (verdict.kind == Verdict::Kind::kForward)
    return callHandler(exchange.sequence,
                       makeRequest(header, head, localAddress_, fromTrustedProxy_, clientGone_));
  answer(exchange.sequence, std::move(verdict.response));
}

void Session::answerParseError(const ErrorCode& ec) {
  const std::string_view received(static_cast<const char*>(buffer_.data().data()), buffer_.size());
  Verdict verdict = checkParseError(ec, *parser_, received, options_);
  const auto& header = parser_->get();
  const Exchange& exchange =
      enqueue(toStd(header.method_string()), toStd(header.target()), 11, false, false);
  beginClosing();
  answer(exchange.sequence, std::move(verdict.response));
}

Session::Exchange& Session::enqueue(std::string_view method, std::string_view target,
                                    unsigned version, bool head, bool keepAlive) {
  Exchange& exchange = queue_.emplace_back();
  exchange.sequence = nextSequence_++;
  if (options_.accessLog) { // the only reader of method and target
    exchange.method = method;
    exchange.target = target;
  }
  exchange.version = version == 10 ? 10 : 11;
  exchange.head = head;
  exchange.keepAlive = keepAlive;
  exchange.start = Clock::now();
  return exchange;
}

void Session::callHandler(std::uint64_t sequence, const Request& request) {
  // `done` may be called from any thread, at most once; the flag also keeps a handler that
  // calls `done` and then throws from being answered twice.
  auto called = std::make_shared<std::atomic<bool>>(false);
  auto done = [self = shared_from_this(), sequence, called](Response response) {
    const bool again = called->exchange(true);
    assert(!again && "http::Handler called done twice");
    if (again)
      return;
    // On the session's own thread (a handler answering at once) there is nothing to hand over.
    if (self->executor_.running_in_this_thread()) {
      self->answer(sequence, std::move(response));
    } else {
      self->postAnswer(sequence, std::move(response));
    }
  };
  try {
    state_->handler()(request, std::move(done));
    return;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "strahler: handler threw for %.200s: %s\n", request.target.c_str(),
                 e.what());
  } catch (...) {
    std::fprintf(stderr, "strahler: handler threw for %.200s\n", request.target.c_str());
  }
  if (!called->exchange(true))
    answer(sequence, errorResponse(500, "internal server error"));
}

void Session::postAnswer(std::uint64_t sequence, Response response) {
  state_->postThroughGate(executor_,
                          [self = shared_from_this(), sequence, r = std::move(response)]() mutable {
                            self->answer(sequence, std::move(r));
                          });
}

void Session::answer(std::uint64_t sequence, Response response) {
  if (phase_ == Phase::kClosed || queue_.empty() || sequence < queue_.front().sequence)
    return;
  const std::uint64_t index = sequence - queue_.front().sequence;
  if (index >= queue_.size())
    return;
  Exchange& exchange = queue_[static_cast<std::size_t>(index)];
  if (exchange.message)
    return;
  // Every 400 closes, the handler's too (a malformed path or query): a client that sent one
  // request we could not make sense of may have framed the next ones wrongly as well.
  if (response.close || response.status == 400) {
    exchange.keepAlive = false;
    beginClosing();
  }
  exchange.route = response.route;
  exchange.message.emplace(toWireResponse(std::move(response), exchange.version, exchange.head));
  maybeWrite();
  updateSheddable();
}

// ---- writing -------------------------------------------------------------------------------

void Session::maybeWrite() {
  if (writing_ || phase_ == Phase::kClosed || queue_.empty() || !queue_.front().message)
    return;
  Exchange& exchange = queue_.front();
  if (state_->draining() && queue_.size() == 1)
    exchange.keepAlive = false;
  const WireResponse& message = *exchange.message;
  head_.clear();
  appendHead(head_, message, exchange.keepAlive, currentHttpDate());
  // One gather write of header and body; the body may be a cached tile, sent without a copy.
  const std::array<net::const_buffer, 2> buffers = {
      net::buffer(head_), message.body ? net::buffer(*message.body) : net::const_buffer()};
  writing_ = true;
  arm(writeDeadline_, options_.writeTimeout);
  net::async_write(socket_, buffers,
                   [self = shared_from_this(), body = message.body](ErrorCode ec, std::size_t) {
                     self->onWrite(ec);
                   });
}

void Session::onWrite(ErrorCode ec) {
  writing_ = false;
  disarm(writeDeadline_);
  if (phase_ == Phase::kClosed || queue_.empty())
    return;
  const Exchange exchange = std::move(queue_.front());
  queue_.pop_front();
  record(exchange, !ec);
  if (ec)
    return closeNow();
  if (!exchange.keepAlive)
    return linger();
  maybeWrite();
  if (phase_ != Phase::kOpen)
    return closeIfIdle();
  doRead(); // resumes reading if the pipelining cap had paused it
  updateSheddable();
}

void Session::record(const Exchange& exchange, bool sent) noexcept {
  const double ms =
      std::chrono::duration<double, std::milli>(Clock::now() - exchange.start).count();
  const std::size_t bytes = sent ? exchange.message->bodyBytes() : 0;
  state_->record(exchange.method, exchange.target, exchange.route,
                 static_cast<int>(exchange.message->status), bytes, ms);
}

/// After the last response: shut the send side and read until the client closes, so that
/// unread request bytes do not turn the close into a reset that could discard the response.
void Session::linger() {
  phase_ = Phase::kLingering;
  updateSheddable();
  queue_.clear(); // requests pipelined after a closing response are not answered
  ErrorCode ignored;
  socket_.shutdown(tcp::socket::shutdown_send, ignored);
  arm(readDeadline_, state_->draining() || shed_ ? kDrainingLingerTimeout : kLingerTimeout);
  if (read_ == Read::kNone)
    discard(); // otherwise the pending read's completion closes
}

void Session::discard() {
  read_ = Read::kDiscard;
  buffer_.clear();
  socket_.async_read_some(buffer_.prepare(kReadChunkBytes), [self = shared_from_this()](
                                                                ErrorCode ec, std::size_t bytes) {
    self->read_ = Read::kNone;
    self->discarded_ += bytes;
    if (ec || self->phase_ == Phase::kClosed || self->discarded_ > kMaxLingerBytes)
      return self->closeNow();
    self->discard();
  });
}

void Session::closeIfIdle() {
  if (queue_.empty() && !writing_)
    closeNow();
}

void Session::onDrain() {
  if (phase_ == Phase::kClosed)
    return;
  beginClosing();
  updateSheddable();
  closeIfIdle(); // otherwise the last owed response goes out with Connection: close
}

void Session::onShed() {
  if (phase_ == Phase::kClosed)
    return;
  shed_ = true;
  if (phase_ != Phase::kOpen || writing_ ||
      !queue_.empty()) // it got busy meanwhile: finish, then close
    return onDrain();
  // A connection still on its first request is answered too, even with nothing read: its
  // request may be in the socket's buffer already, and a client retries by itself only on a
  // connection it has used before.
  if (read_ == Read::kHeader &&
      (firstRequest() || buffer_.size() > 0 || (parser_ && parser_->got_some())))
    return answerAndClose(503, "too many connections: this one had the oldest incomplete "
                               "request header; retry later");
  closeNow(); // idle: a client reopens a closed keep-alive connection by itself
}

/// Answers the request whose header is being read with `status` and closes; the pending read
/// completes into the linger that follows the response.
void Session::answerAndClose(int status, const std::string& message) {
  const auto& header = parser_->get();
  const Exchange& exchange =
      enqueue(toStd(header.method_string()), toStd(header.target()), 11, false, false);
  beginClosing();
  Response response = errorResponse(status, message);
  if (status == 503)
    response.headers.emplace_back("Retry-After", "1");
  answer(exchange.sequence, std::move(response));
}

void Session::updateSheddable() noexcept {
  const bool sheddable =
      read_ != Read::kNone && phase_ == Phase::kOpen && !writing_ && queue_.empty();
  if (sheddable == (sheddableSince_.load(std::memory_order_relaxed) != 0))
    return;
  const Ticks now = std::max<Ticks>(1, Clock::now().time_since_epoch().count());
  sheddableSince_.store(sheddable ? now : 0, std::memory_order_relaxed);
}

// ---- timers --------------------------------------------------------------------------------

void Session::arm(Deadline& deadline, Duration timeout) {
  deadline.timeout = timeout;
  deadline.at = Clock::now() + timeout;
  deadline.armed = true;
  if (!deadline.waiting || deadline.at < deadline.wakeAt)
    wait(deadline);
}

void Session::wait(Deadline& deadline) {
  deadline.waiting = true;
  deadline.wakeAt = deadline.at;
  const std::uint64_t generation = ++deadline.generation;
  deadline.timer.expires_at(deadline.at); // a pending wait wakes with a stale generation
  deadline.timer.async_wait([self = shared_from_this(), &deadline, generation](ErrorCode) {
    self->onWake(deadline, generation);
  });
}

void Session::onWake(Deadline& deadline, std::uint64_t generation) {
  if (generation != deadline.generation)
    return;
  deadline.waiting = false;
  if (phase_ == Phase::kClosed || !deadline.armed)
    return;
  if (Clock::now() < deadline.at)
    return wait(deadline);
  deadline.armed = false;
  if (&deadline == &writeDeadline_) {
    if (writing_)
      closeNow();
    return;
  }
  onReadTimeout();
}

void Session::onReadTimeout() {
  if (read_ == Read::kNone)
    return;
  // A client waiting for owed responses is not slow: only an idle connection times out.
  if (phase_ != Phase::kLingering && !queue_.empty())
    return arm(readDeadline_, readDeadline_.timeout);
  if (read_ == Read::kHeader && phase_ == Phase::kOpen) // an idle one closes without a word
    return answerAndClose(408, "request header not complete within " +
                                   std::to_string(options_.headerTimeout.count()) + " ms");
  closeNow();
}

void Session::cancel(Deadline& deadline) noexcept {
  deadline.armed = false;
  try {
    deadline.timer.cancel();
  } catch (...) {
  }
}

} // namespace strahler::http::detail
