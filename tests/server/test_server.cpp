#include "test_server.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace strahler::http::test {
namespace {

Response text(std::string body, int status = 200) {
  Response response;
  response.status = status;
  response.headers.emplace_back("Content-Type", "text/plain");
  response.body = std::move(body);
  response.route = "echo";
  return response;
}

} // namespace

ServerOptions testOptions() {
  ServerOptions options;
  options.host = "127.0.0.1";
  options.port = 0;
  options.ioThreads = 2;
  options.accessLog = false;
  options.headerTimeout = std::chrono::milliseconds(2000);
  options.idleTimeout = std::chrono::milliseconds(2000);
  options.writeTimeout = std::chrono::milliseconds(2000);
  return options;
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

TestServer::TestServer(ServerOptions options)
    : server_(
          std::move(options),
          [this](const Request& request, std::function<void(Response)> done) {
            handle(request, std::move(done));
          },
          [this](const std::string& route, int status, std::size_t bytes, double) {
            std::lock_guard lock(mutex_);
            observations_.push_back({route, status, bytes});
          }) {
  const auto status = server_.start();
  EXPECT_TRUE(status.ok()) << (status.ok() ? "" : status.error().message);
}

TestServer::~TestServer() {
  server_.stop(std::chrono::milliseconds(1000));
  releaseHung();
  std::vector<std::thread> workers;
  {
    std::lock_guard lock(mutex_);
    workers.swap(workers_);
  }
  for (auto& worker : workers)
    worker.join();
}

std::vector<Observation> TestServer::observations() const {
  std::lock_guard lock(mutex_);
  return observations_;
}

int TestServer::hungClientsGone() const {
  std::lock_guard lock(mutex_);
  int gone = 0;
  for (const auto& flag : hungGone_)
    gone += flag && flag->load() ? 1 : 0;
  return gone;
}

void TestServer::releaseHung() {
  std::vector<std::function<void(Response)>> pending;
  {
    std::lock_guard lock(mutex_);
    pending.swap(hungDone_);
  }
  for (auto& done : pending)
    done(text("released"));
}

void TestServer::later(std::function<void()> work) {
  std::lock_guard lock(mutex_);
  workers_.emplace_back(std::move(work));
}

void TestServer::handle(const Request& request, std::function<void(Response)> done) {
  ++calls_;
  const std::string& target = request.target;
  if (target.rfind("/slow", 0) == 0) {
    const int inFlight = ++slowInFlight_;
    for (int peak = slowPeak_.load();
         peak < inFlight && !slowPeak_.compare_exchange_weak(peak, inFlight);)
      ;
    return later([this, target, done = std::move(done)] {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      --slowInFlight_;
      done(text(target));
    });
  }
  if (target == "/throw")
    throw std::runtime_error("handler failure");
  if (target == "/big")
    return done(text(std::string(1 << 20, 'b')));
  if (target == "/huge")
    return done(text(std::string(16 << 20, 'h')));
  if (target == "/hang") {
    std::lock_guard lock(mutex_);
    hungDone_.push_back(std::move(done));
    hungGone_.push_back(request.clientGone);
    ++hung_;
    return;
  }
  if (target == "/close") {
    Response response = text("bye");
    response.close = true;
    return done(std::move(response));
  }
  if (target.rfind("/status/", 0) == 0)
    return done(text("status", std::stoi(target.substr(8))));
  if (target == "/evil") {
    Response response = text("evil");
    response.headers.emplace_back("X-Evil", "a\r\nInjected: yes");
    response.headers.emplace_back("Content-Length", "999");
    return done(std::move(response));
  }
  if (target == "/twice") {
    done(text("first"));
    return done(text("second")); // a handler bug: asserts in debug builds, ignored otherwise
  }
  if (target.rfind("/fields/", 0) == 0) { // /fields/N[?prepared]
    Response response = text("fields", std::stoi(target.substr(8, 3)));
    response.headers.emplace_back("ETag", "\"e\"");
    response.headers.emplace_back("X-Padded", " \t padded value \t ");
    response.headers.emplace_back("server", "not this one");
    response.headers.emplace_back("X-Bad", "a\r\nInjected: yes");
    if (target.ends_with("?prepared")) { // the fields must come from the prepared ones alone
      response.preparedFields = std::make_shared<const std::string>(prepareFields(response));
      response.headers.clear();
    }
    return done(std::move(response));
  }
  if (target == "/x-test")
    return done(text(request.header("x-test")));
  Response response = text(target);
  response.headers.emplace_back("X-Head", request.head ? "1" : "0");
  response.headers.emplace_back("X-Method", request.method);
  response.headers.emplace_back("ETag", "\"v1\"");
  done(std::move(response));
}

} // namespace strahler::http::test
