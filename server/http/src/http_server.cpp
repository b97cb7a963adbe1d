#include "strahler/http/http_server.h"

#include "listener.h"
#include "net.h"
#include "server_state.h"
#include "session.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace strahler::http {
namespace {

using detail::ErrorCode;
namespace net = detail::net;
using detail::tcp;
using Clock = std::chrono::steady_clock;

/// How long stop() waits for force-closed connections before stopping the event loop anyway.
constexpr std::chrono::milliseconds kForceCloseWait{200};

base::Status validate(const ServerOptions& o) {
  const auto invalid = [](const char* what) {
    return base::makeError(base::ErrorCode::kInvalidInput, std::string("server option ") + what);
  };
  if (o.ioThreads < 1)
    return invalid("ioThreads must be at least 1");
  if (o.maxConnections < 1)
    return invalid("maxConnections must be at least 1");
  if (o.maxPipelined < 1)
    return invalid("maxPipelined must be at least 1");
  if (o.maxTargetBytes < 1)
    return invalid("maxTargetBytes must be at least 1");
  if (o.maxHeaderBytes < 64)
    return invalid("maxHeaderBytes must be at least 64");
  const auto zero = std::chrono::milliseconds::zero();
  if (o.headerTimeout <= zero || o.idleTimeout <= zero || o.writeTimeout <= zero)
    return invalid("timeouts must be positive");
  return base::Ok{};
}

base::Result<tcp::endpoint> resolve(net::io_context& io, const std::string& host,
                                    std::uint16_t port) {
  ErrorCode ec;
  const auto address = net::ip::make_address(host, ec);
  if (!ec)
    return tcp::endpoint(address, port);
  tcp::resolver resolver(io);
  const auto results = resolver.resolve(host, std::to_string(port), ec);
  if (ec || results.empty())
    return base::makeError(base::ErrorCode::kIoError,
                           "cannot resolve host '" + host + "': " + ec.message());
  return results.begin()->endpoint();
}

/// Runs the event loop until it is stopped; an exception escaping a completion handler is
/// reported and the loop resumes, so no request can end an I/O thread.
void runEventLoop(net::io_context& io) {
  for (;;) {
    try {
      io.run();
      return;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "strahler: I/O thread caught: %s\n", e.what());
    } catch (...) {
      std::fprintf(stderr, "strahler: I/O thread caught an unknown exception\n");
    }
  }
}

} // namespace

struct Server::Impl {
  ServerOptions options;
  Handler handler;
  RequestObserver observer;
  std::mutex lifecycle; ///< Serialises start() and stop().
  bool started = false;
  bool stopped = false;
  std::shared_ptr<detail::ServerState> state;
  std::shared_ptr<detail::Listener> listener;
  std::vector<net::executor_work_guard<net::io_context::executor_type>> work;
  std::vector<std::thread> threads;
  std::atomic<std::uint16_t> port{0};
  std::atomic<const detail::ServerState*> published{nullptr}; ///< For connections().

  void closeConnections(Clock::time_point deadline);
  void joinThreads();
  void finalCleanup();
};

Server::Server(ServerOptions options, Handler handler, RequestObserver observer)
    : impl_(std::make_unique<Impl>()) {
  impl_->options = std::move(options);
  impl_->handler = std::move(handler);
  impl_->observer = std::move(observer);
}

Server::~Server() {
  stop();
}

base::Status Server::start() {
  Impl& impl = *impl_;
  std::lock_guard lock(impl.lifecycle);
  if (impl.started || impl.stopped)
    return base::makeError(base::ErrorCode::kInternal, "Server::start() called twice");
  STRAHLER_RETURN_IF_ERROR(validate(impl.options));
  auto state = std::make_shared<detail::ServerState>(impl.options, impl.handler, impl.observer);
  STRAHLER_ASSIGN_OR_RETURN(
      const tcp::endpoint endpoint,
      resolve(*state->ioContexts().front(), impl.options.host, impl.options.port));
  auto listener = std::make_shared<detail::Listener>(state);
  STRAHLER_RETURN_IF_ERROR(listener->open(endpoint));
  impl.state = std::move(state);
  impl.listener = std::move(listener);
  impl.published.store(impl.state.get());
  impl.port.store(impl.listener->port());
  for (const auto& io : impl.state->ioContexts())
    impl.work.push_back(net::make_work_guard(*io));
  impl.listener->run();
  for (const auto& io : impl.state->ioContexts())
    impl.threads.emplace_back([&loop = *io] { runEventLoop(loop); });
  impl.started = true;
  return base::Ok{};
}

std::uint16_t Server::port() const noexcept {
  return impl_->port.load();
}

std::size_t Server::connections() const noexcept {
  const detail::ServerState* state = impl_->published.load();
  return state ? state->connections() : 0;
}

void Server::stop(std::chrono::milliseconds drain) {
  Impl& impl = *impl_;
  std::lock_guard lock(impl.lifecycle);
  const bool running = impl.started && !impl.stopped;
  impl.stopped = true;
  if (!running)
    return;
  for (const auto& thread : impl.threads)
    STRAHLER_ASSERT(thread.get_id() != std::this_thread::get_id(),
                    "Server::stop() called from an I/O thread");
  impl.closeConnections(Clock::now() + std::max(drain, std::chrono::milliseconds::zero()));
  impl.joinThreads();
  impl.finalCleanup();
}

/// Stops accepting, lets sessions finish what they owe until `deadline`, then closes the rest.
void Server::Impl::closeConnections(Clock::time_point deadline) {
  state->startDraining();
  listener->stop();
  for (const auto& session : state->sessions())
    session->drain();
  if (state->waitUntilIdle(deadline))
    return;
  for (const auto& session : state->sessions())
    session->forceClose();
  state->waitUntilIdle(Clock::now() + kForceCloseWait);
}

void Server::Impl::joinThreads() {
  work.clear();
  for (const auto& io : state->ioContexts())
    io->stop();
  for (auto& thread : threads)
    thread.join();
  threads.clear();
}

/// With no I/O thread left: drop late completions from workers, close whatever is still open
/// and run the remaining completion handlers, so none keeps a session (and the io_context)
/// alive through a reference cycle.
void Server::Impl::finalCleanup() {
  state->closeGate();
  for (const auto& io : state->ioContexts())
    io->restart();
  listener->closeNow();
  for (const auto& session : state->sessions())
    session->closeNow();
  for (bool ran = true; ran;) {
    ran = false;
    for (const auto& io : state->ioContexts())
      ran = io->poll() > 0 || ran;
  }
}

} // namespace strahler::http
