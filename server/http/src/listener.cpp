#include "listener.h"

#include "session.h"
#include "wire_response.h"

#include <boost/beast/core/bind_handler.hpp>

#include <cstdio>
#include <sstream>
#include <string>

namespace strahler::http::detail {
namespace {

base::Error listenError(const char* step, const tcp::endpoint& endpoint, const ErrorCode& ec) {
  std::ostringstream message;
  message << "cannot " << step << " " << endpoint << ": " << ec.message();
  return base::makeError(base::ErrorCode::kIoError, message.str());
}

/// Errors of one aborted connection, not of the listening socket: accept again at once.
bool isPeerError(const ErrorCode& ec) {
  return ec == net::error::connection_aborted || ec == net::error::connection_reset;
}

} // namespace

Listener::Listener(std::shared_ptr<ServerState> state)
    : state_(std::move(state)), acceptor_(state_->ioContexts().front()->get_executor()),
      retryTimer_(acceptor_.get_executor()) {}

base::Status Listener::open(const tcp::endpoint& endpoint) {
  ErrorCode ec;
  acceptor_.open(endpoint.protocol(), ec);
  if (ec)
    return listenError("open a socket for", endpoint, ec);
  acceptor_.set_option(net::socket_base::reuse_address(true), ec);
  if (ec)
    return listenError("set SO_REUSEADDR on", endpoint, ec);
  acceptor_.bind(endpoint, ec);
  if (ec)
    return listenError("bind", endpoint, ec);
  acceptor_.listen(net::socket_base::max_listen_connections, ec);
  if (ec)
    return listenError("listen on", endpoint, ec);
  port_ = acceptor_.local_endpoint(ec).port();
  if (ec)
    return listenError("read the address of", endpoint, ec);
  return base::Ok{};
}

void Listener::run() {
  net::post(acceptor_.get_executor(), [self = shared_from_this()] { self->doAccept(); });
}

void Listener::stop() {
  net::post(acceptor_.get_executor(), [self = shared_from_this()] { self->closeNow(); });
}

void Listener::closeNow() noexcept {
  stopped_ = true;
  ErrorCode ignored;
  acceptor_.close(ignored);
  try {
    retryTimer_.cancel();
  } catch (...) {
  }
}

void Listener::doAccept() {
  if (stopped_)
    return;
  acceptor_.async_accept(state_->nextIoContext(),
                         beast::bind_front_handler(&Listener::onAccept, shared_from_this()));
}

void Listener::onAccept(ErrorCode ec, Socket socket) {
  if (stopped_ || ec == net::error::operation_aborted)
    return;
  if (ec)
    return onAcceptError(ec);
  failing_ = false;
  if (state_->draining()) {
    refuse(std::move(socket), "the server is shutting down");
    return doAccept();
  }
  ErrorCode peerError;
  const tcp::endpoint peer = socket.remote_endpoint(peerError);
  if (peerError) // the client has gone already
    return doAccept();
  try {
    std::string client = clientKey(peer.address());
    switch (state_->admit(client)) {
    case ServerState::Admission::kRefuseClient:
      refuse(std::move(socket), "too many connections from your address; retry later");
      break;
    case ServerState::Admission::kRefuseFull:
      refuse(std::move(socket), "too many connections; retry later");
      break;
    case ServerState::Admission::kAccept:
      std::make_shared<Session>(state_, std::move(socket), std::move(client))->start();
      break;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "strahler: cannot start a connection: %s\n", e.what());
  }
  doAccept();
}

void Listener::onAcceptError(const ErrorCode& ec) {
  if (isPeerError(ec))
    return doAccept();
  if (!failing_)
    std::fprintf(stderr, "strahler: accept failed (%s); retrying every %lld ms\n",
                 ec.message().c_str(), static_cast<long long>(kAcceptRetryDelay.count()));
  failing_ = true;
  retryTimer_.expires_after(kAcceptRetryDelay);
  retryTimer_.async_wait([self = shared_from_this()](ErrorCode timerError) {
    if (!timerError)
      self->doAccept();
  });
}

/// Writes a 503 without blocking (a fresh socket's send buffer takes it) and closes.
void Listener::refuse(Socket socket, const char* reason) noexcept {
  try {
    Response response = errorResponse(503, reason);
    response.headers.emplace_back("Retry-After", "1");
    const WireResponse wire = toWireResponse(std::move(response), 11, false);
    std::string bytes;
    appendHead(bytes, wire, false, currentHttpDate());
    bytes += *wire.body;
    ErrorCode ignored;
    socket.non_blocking(true, ignored);
    socket.write_some(net::buffer(bytes), ignored);
    socket.shutdown(tcp::socket::shutdown_both, ignored);
    socket.close(ignored);
    state_->record("-", "-", "error", 503, wire.bodyBytes(), 0.0);
  } catch (...) {
    // Out of memory while refusing: the socket closes with its destructor.
  }
}

} // namespace strahler::http::detail
