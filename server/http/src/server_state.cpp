#include "server_state.h"

#include "access_log.h"
#include "session.h"

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

std::string clientKey(const net::ip::address& address) {
  if (address.is_v4())
    return address.to_v4().to_string();
  const net::ip::address_v6 v6 = address.to_v6();
  if (v6.is_v4_mapped())
    return net::ip::make_address_v4(net::ip::v4_mapped, v6).to_string();
  net::ip::address_v6::bytes_type prefix = v6.to_bytes();
  std::fill(prefix.begin() + 8, prefix.end(), static_cast<unsigned char>(0));
  return net::ip::address_v6(prefix).to_string() + "/64";
}

ServerState::Admission ServerState::admit(const std::string& client) {
  std::shared_ptr<Session> victim;
  Admission admission = Admission::kAccept;
  {
    std::lock_guard lock(mutex_);
    const auto held = clients_.find(client);
    bool found = false;
    if (options_.maxConnectionsPerClient > 0 && held != clients_.end() &&
        held->second >= options_.maxConnectionsPerClient) {
      victim = pickVictim(&client, found);
      admission = found ? Admission::kAccept : Admission::kRefuseClient;
    } else if (counted_ >= options_.maxConnections) {
      victim = pickVictim(nullptr, found);
      admission = found ? Admission::kAccept : Admission::kRefuseFull;
    }
  }
  if (victim)
    victim->shed();
  return admission;
}

std::shared_ptr<Session> ServerState::pickVictim(const std::string* client, bool& found) {
  Registered* oldest = nullptr;
  Session::Ticks oldestSince = 0;
  for (auto& [key, entry] : sessions_) {
    if (entry.shed || (client && entry.client != *client))
      continue;
    // The session is alive while registered: its destructor unregisters under this lock.
    const Session::Ticks since = key->sheddableSince();
    if (since != 0 && (!oldest || since < oldestSince)) {
      oldest = &entry;
      oldestSince = since;
    }
  }
  found = oldest != nullptr;
  if (!oldest)
    return nullptr;
  oldest->shed = true;
  uncount(oldest->client);
  return oldest->session.lock(); // null while it is being destroyed: it closes anyway
}

void ServerState::uncount(const std::string& client) noexcept {
  --counted_;
  if (const auto held = clients_.find(client); held != clients_.end() && --held->second == 0)
    clients_.erase(held);
}

void ServerState::add(const std::shared_ptr<Session>& session, const std::string& client) {
  std::lock_guard lock(mutex_);
  if (!sessions_.emplace(session.get(), Registered{session, client}).second)
    return;
  connections_.fetch_add(1);
  ++counted_;
  ++clients_[client];
}

void ServerState::remove(const Session* session) noexcept {
  {
    std::lock_guard lock(mutex_);
    const auto found = sessions_.find(session);
    if (found == sessions_.end())
      return;
    if (!found->second.shed)
      uncount(found->second.client);
    sessions_.erase(found);
    connections_.fetch_sub(1);
  }
  idle_.notify_all();
}

std::vector<std::shared_ptr<Session>> ServerState::sessions() const {
  std::vector<std::shared_ptr<Session>> open;
  std::lock_guard lock(mutex_);
  open.reserve(sessions_.size());
  for (const auto& [key, entry] : sessions_)
    if (auto session = entry.session.lock())
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
