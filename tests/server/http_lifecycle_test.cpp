// Limits and lifecycle: timeouts that hold or cut a connection, the connection cap, start()
// errors. The bounds on elapsed time are in http_timing_test.cpp.
#include "test_client.h"
#include "test_server.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace strahler::http::test {
namespace {

using namespace std::chrono_literals;

TEST(HttpServer, SlowHandlerOutlivesTheIdleTimeout) {
  ServerOptions options = testOptions();
  options.idleTimeout = 50ms;
  TestServer server(options);
  Connection connection(server.port());
  ASSERT_TRUE(connection.send(getRequest("/one") + getRequest("/slow")));
  ASSERT_TRUE(connection.read());
  const auto slow = connection.read(); // the idle read-ahead waits for the owed response
  ASSERT_TRUE(slow);
  EXPECT_EQ(slow->body, "/slow");
}

TEST(HttpServer, ClientThatStopsReadingIsCutOffByTheWriteTimeout) {
  ServerOptions options = testOptions();
  options.writeTimeout = 200ms;
  TestServer server(options);
  Connection connection(server.port(), 5000ms, /*receiveBuffer=*/4096);
  ASSERT_TRUE(connection.send(getRequest("/huge")));
  std::this_thread::sleep_for(600ms); // read nothing: the 16 MiB write stalls and times out
  const std::string received = connection.readUntilClose(3000ms);
  EXPECT_LT(received.size(), std::size_t{16} << 20);
  EXPECT_TRUE(eventually([&] { return server.server().connections() == 0; }, 1000ms));
}

TEST(HttpServer, ConnectionsBeyondTheCapAreRefusedWhenNoneIsIdle) {
  ServerOptions options = testOptions();
  options.maxConnections = 4;
  TestServer server(options);
  std::vector<std::unique_ptr<Connection>> admitted;
  for (int i = 0; i < 4; ++i) { // busy: each waits for its response, so none can be shed
    admitted.push_back(std::make_unique<Connection>(server.port()));
    ASSERT_TRUE(admitted.back()->send(getRequest("/hang")));
  }
  ASSERT_TRUE(eventually([&] { return server.hungCount() == 4; }, 2000ms));
  EXPECT_EQ(server.server().connections(), 4u);
  for (int i = 0; i < 2; ++i) {
    Connection refused(server.port());
    const std::string bytes = refused.readUntilClose(2000ms);
    EXPECT_EQ(bytes.rfind("HTTP/1.1 503 ", 0), 0u) << bytes;
    EXPECT_NE(bytes.find("Retry-After: 1\r\n"), std::string::npos);
  }
  server.releaseHung();
  for (auto& connection : admitted) { // the admitted ones still work
    const auto hung = connection->read();
    ASSERT_TRUE(hung);
    EXPECT_EQ(hung->status, 200);
    ASSERT_TRUE(connection->send(getRequest("/again")));
    EXPECT_TRUE(connection->read());
  }
  admitted.pop_back();
  ASSERT_TRUE(eventually([&] { return server.server().connections() == 3; }, 1000ms));
  const auto response = fetch(server.port(), getRequest("/room"));
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 200);
}

TEST(HttpServer, StartFailsOnAPortInUse) {
  TestServer first;
  ServerOptions options = testOptions();
  options.port = first.port();
  Server second(options, [](const Request&, std::function<void(Response)> done) { done({}); });
  const auto status = second.start();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, base::ErrorCode::kIoError);
  second.stop();
}

TEST(HttpServer, InvalidOptionsAreRejected) {
  ServerOptions options = testOptions();
  options.maxPipelined = 0;
  Server server(options, [](const Request&, std::function<void(Response)> done) { done({}); });
  const auto status = server.start();
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().code, base::ErrorCode::kInvalidInput);
}

} // namespace
} // namespace strahler::http::test
