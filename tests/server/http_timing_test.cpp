// Bounds on elapsed time: the header and idle timeouts, stop() and its drain, and the CPU the
// accept loop spends out of descriptors. Labelled `timing`: the sanitized run leaves it out.
#include "test_client.h"
#include "test_server.h"

#include <gtest/gtest.h>

#include <future>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace strahler::http::test {
namespace {

using namespace std::chrono_literals;

TEST(HttpServer, HalfARequestLineIsDisconnectedAfterTheHeaderTimeout) {
  ServerOptions options = testOptions();
  options.headerTimeout = 300ms;
  TestServer server(options);
  Connection connection(server.port());
  const auto start = std::chrono::steady_clock::now();
  ASSERT_TRUE(connection.send("GET /slowl"));
  EXPECT_TRUE(connection.closedWithin(1500ms));
  EXPECT_GE(msSince(start), 280.0);
  EXPECT_LT(msSince(start), 1400.0); // generous: CI machines are loaded
  EXPECT_TRUE(eventually([&] { return server.server().connections() == 0; }, 1000ms));
}

TEST(HttpServer, TricklingHeadersDoNotExtendTheHeaderTimeout) {
  ServerOptions options = testOptions();
  options.headerTimeout = 300ms;
  TestServer server(options);
  Connection connection(server.port());
  const auto start = std::chrono::steady_clock::now();
  ASSERT_TRUE(connection.send("GET / HTTP/1.1\r\n"));
  bool closed = false;
  for (int i = 0; i < 20 && !closed; ++i) {
    connection.send("X-A: b\r\n"); // fails once the server has closed
    closed = connection.closedWithin(50ms);
  }
  EXPECT_TRUE(closed);
  EXPECT_LT(msSince(start), 1400.0); // generous: CI machines are loaded
}

TEST(HttpServer, IdleKeepAliveConnectionIsClosedAfterTheIdleTimeout) {
  ServerOptions options = testOptions();
  options.idleTimeout = 300ms;
  TestServer server(options);
  Connection connection(server.port());
  ASSERT_TRUE(connection.send(getRequest("/one")));
  ASSERT_TRUE(connection.read());
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(connection.closedWithin(1500ms));
  EXPECT_GE(msSince(start), 280.0);
  EXPECT_LT(msSince(start), 1400.0); // generous: CI machines are loaded
}

double cpuSeconds() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

/// Lowers RLIMIT_NOFILE and takes every free descriptor but `spare`; undoes it all on release.
class DescriptorSqueeze {
public:
  explicit DescriptorSqueeze(int spare) {
    ::getrlimit(RLIMIT_NOFILE, &original_);
    rlimit tight = original_;
    tight.rlim_cur = static_cast<rlim_t>(::dup(0) + 32); // just above what is in use now
    ::close(static_cast<int>(tight.rlim_cur) - 32);
    ::setrlimit(RLIMIT_NOFILE, &tight);
    for (int fd; (fd = ::dup(0)) >= 0;)
      taken_.push_back(fd);
    for (int i = 0; i < spare && !taken_.empty(); ++i) {
      ::close(taken_.back());
      taken_.pop_back();
    }
  }
  ~DescriptorSqueeze() { release(); }
  DescriptorSqueeze(const DescriptorSqueeze&) = delete;
  DescriptorSqueeze& operator=(const DescriptorSqueeze&) = delete;

  /// Gives the descriptors back and restores the limit.
  void release() {
    for (int fd : taken_)
      ::close(fd);
    taken_.clear();
    ::setrlimit(RLIMIT_NOFILE, &original_);
  }

private:
  rlimit original_{};
  std::vector<int> taken_;
};

TEST(HttpServer, AcceptBacksOffWhenOutOfDescriptorsAndRecovers) {
  TestServer server;
  ASSERT_TRUE(fetch(server.port(), getRequest("/warm")));
  ASSERT_TRUE(eventually([&] { return server.server().connections() == 0; }, 1000ms));
  DescriptorSqueeze squeeze(/*spare=*/1);
  Connection starved(server.port()); // takes the one spare descriptor; accept() gets EMFILE
  ASSERT_TRUE(starved.connected());
  ASSERT_TRUE(starved.send(getRequest("/starved")));
  const double cpuBefore = cpuSeconds();
  std::this_thread::sleep_for(300ms);
  const double cpuUsed = cpuSeconds() - cpuBefore;
  EXPECT_EQ(server.server().connections(), 0u);
  squeeze.release();
  EXPECT_LT(cpuUsed, 0.15) << "the accept loop spins while out of descriptors";
  const auto response = starved.read(); // accepted from the backlog once descriptors are back
  ASSERT_TRUE(response);
  EXPECT_EQ(response->body, "/starved");
  const auto after = fetch(server.port(), getRequest("/after"));
  ASSERT_TRUE(after);
  EXPECT_EQ(after->status, 200);
}

TEST(HttpServer, StopLetsAnInFlightRequestFinish) {
  TestServer server;
  Connection busy(server.port());
  Connection idle(server.port());
  ASSERT_TRUE(idle.send(getRequest("/idle")));
  ASSERT_TRUE(idle.read());
  ASSERT_TRUE(busy.send(getRequest("/slow")));
  ASSERT_TRUE(eventually([&] { return server.handlerCalls() == 2; }, 1000ms));
  const auto start = std::chrono::steady_clock::now();
  auto stopped = std::async(std::launch::async, [&] { server.server().stop(4000ms); });
  const auto response = busy.read();
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 200);
  EXPECT_EQ(response->body, "/slow");
  EXPECT_EQ(response->header("connection"), "close");
  EXPECT_TRUE(idle.closedWithin(1000ms));
  ASSERT_EQ(stopped.wait_for(2s), std::future_status::ready);
  EXPECT_LT(msSince(start), 1000.0);
  EXPECT_EQ(server.server().connections(), 0u);
  EXPECT_FALSE(fetch(server.port(), getRequest("/gone")));
}

TEST(HttpServer, StopGivesUpOnAHungHandlerAfterTheDrainTime) {
  TestServer server;
  Connection hung(server.port());
  ASSERT_TRUE(hung.send(getRequest("/hang")));
  ASSERT_TRUE(eventually([&] { return server.hungCount() == 1; }, 1000ms));
  const auto start = std::chrono::steady_clock::now();
  server.server().stop(300ms);
  const double took = msSince(start);
  EXPECT_GE(took, 290.0);
  EXPECT_LT(took, 1300.0);
  EXPECT_TRUE(hung.closedWithin(500ms));
  server.releaseHung();   // a late `done` after stop() is dropped, not a crash
  server.server().stop(); // idempotent
}

} // namespace
} // namespace strahler::http::test
