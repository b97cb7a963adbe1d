#include "server_state.h"

#include "access_log.h"

#include <algorithm>
#include <cstdio>
#include <exception>

namespace strahler::http::detail {

ServerState::ServerState(ServerOptions options, Handler handler, RequestObserver observer)
    : options_(std::move(options)), handler_(std::move(handler)), observer_(std::move(observer)) {
  for (int i = 0; i < std::max(1, options_.ioThreads); ++i)
    ioContexts_.push_back(std::make_unique<net::io_context>(1)); // one thread runs each
}

net::io_context& ServerState::nextIoContext() noexcept {
  return *ioContexts_[nextIoContext_.fetch_add(1, std::memory_order_relaxed) % ioContexts_.size()];
}

void ServerState::add(const std::shared_ptr<Session>& session) {
  std::lock_guard lock(mutex_);
  if (sessions_.emplace(session.get(), session).second)
    connections_.fetch_add(1);
}

void ServerState::remove(const Session* session) noexcept {
  {
    std::lock_guard lock(mutex_);
    if (sessions_.erase(session) == 0)
      return;
    connections_.fetch_sub(1);
  }
  idle_.notify_all();
}

std::vector<std::shared_ptr<Session>> ServerState::sessions() const {
  std::vector<std::shared_ptr<Session>> open;
  std::lock_guard lock(mutex_);
  open.reserve(sessions_.size());
  for (const auto& [key, weak] : sessions_)
    if (auto session = weak.lock())
      open.push_back(std::move(session));
  return open;
}

bool ServerState::waitUntilIdle(std::chrono::steady_clock::time_point deadline) {
  std::unique_lock lock(mutex_);
  return idle_.wait_until(lock, deadline, [this] { return sessions_.empty(); });
}

void ServerState::closeGate() noexcept {
  std::lock_guard lock(mutex_);
  gateOpen_ = false;
}

void ServerState::record(std::string_view method, std::string_view target, const std::string& route,
                         int status, std::size_t bytes, double ms) noexcept {
  try {
    if (options_.accessLog)
      writeAccessLine(formatAccessLine(method, target, status, bytes, ms));
    if (observer_)
      observer_(route, status, bytes, ms);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "strahler: request observer failed: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "strahler: request observer failed\n");
  }
}

} // namespace strahler::http::detail
