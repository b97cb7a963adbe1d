// One client cannot take every connection (issue 17, item 2): the per-client limit, shedding of
// idle and header-incomplete connections at the cap, and 408 on a header timeout. Test clients
// bind 127.0.0.x source addresses (Linux routes all of 127/8 on loopback) to be several clients.
#include "test_client.h"
#include "test_server.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace strahler::http::test {
namespace {

using namespace std::chrono_literals;

/// A request header that never ends: the connection stays header-incomplete.
constexpr std::string_view kSlowHeader = "GET /slowloris HTTP/1.1\r\nHost: x\r\nX-Slow: ";

TEST(HttpFairness, ManySlowConnectionsFromOneAddressLeaveRoomForOtherClients) {
  ServerOptions options = testOptions();
  options.maxConnections = 64;
  options.maxConnectionsPerClient = 16;
  options.headerTimeout = 10s; // the slow connections do not simply time out meanwhile
  TestServer server(options);
  // 200 slowloris connections from 127.0.0.1, more than three times the whole cap.
  std::vector<std::unique_ptr<Connection>> slow;
  for (int i = 0; i < 200; ++i) {
    slow.push_back(std::make_unique<Connection>(server.port(), 2000ms, 0, "127.0.0.1"));
    ASSERT_TRUE(slow.back()->connected()) << i;
    slow.back()->send(kSlowHeader); // may fail: the server may have shed it already
  }
  EXPECT_TRUE(eventually([&] { return server.server().connections() <= 16; }, 2000ms))
      << server.server().connections() << " connections held";
  // Normal clients on eight other addresses, four connections each, all at the same time.
  std::vector<std::unique_ptr<Connection>> normal;
  for (int a = 2; a < 10; ++a)
    for (int i = 0; i < 4; ++i) {
      normal.push_back(
          std::make_unique<Connection>(server.port(), 2000ms, 0, "127.0.0." + std::to_string(a)));
      ASSERT_TRUE(normal.back()->send(getRequest("/normal"))) << "client 127.0.0." << a;
    }
  for (auto& connection : normal) {
    const auto response = connection->read();
    ASSERT_TRUE(response);
    EXPECT_EQ(response->status, 200) << response->body;
  }
  EXPECT_TRUE(
      eventually([&] { return server.server().connections() <= 16u + normal.size(); }, 1000ms))
      << server.server().connections() << " connections held";
}

TEST(HttpFairness, AClientAtItsLimitShedsItsOwnOldestSlowConnection) {
  ServerOptions options = testOptions();
  options.maxConnectionsPerClient = 3;
  TestServer server(options);
  std::vector<std::unique_ptr<Connection>> slow;
  for (int i = 0; i < 3; ++i) {
    slow.push_back(std::make_unique<Connection>(server.port(), 2000ms, 0, "127.0.0.5"));
    ASSERT_TRUE(slow.back()->send(kSlowHeader));
    ASSERT_TRUE(eventually([&] { return server.server().connections() == slow.size(); }, 1000ms));
  }
  const auto response = fetch(server.port(), getRequest("/mine"), 2000ms, "127.0.0.5");
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 200);
  const std::string oldest = slow.front()->readUntilClose(1000ms);
  EXPECT_EQ(oldest.rfind("HTTP/1.1 503 ", 0), 0u) << oldest;
  EXPECT_NE(oldest.find("Retry-After: 1\r\n"), std::string::npos) << oldest;
  EXPECT_NE(oldest.find("oldest incomplete request header"), std::string::npos) << oldest;
  EXPECT_FALSE(slow[1]->closedWithin(100ms)) << "a younger connection was shed";
}

TEST(HttpFairness, AFreshConnectionShedBeforeItsRequestIsReadIsAnswered503) {
  // Nothing read yet looks idle, but the request may already sit in the socket's buffer (the
  // server is busy): closing without a word would lose it, as clients retry only on reused
  // connections.
  ServerOptions options = testOptions();
  options.maxConnectionsPerClient = 1;
  TestServer server(options);
  Connection fresh(server.port(), 2000ms, 0, "127.0.0.6");
  ASSERT_TRUE(eventually([&] { return server.server().connections() == 1; }, 1000ms));
  const auto response = fetch(server.port(), getRequest("/mine"), 2000ms, "127.0.0.6");
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 200);
  const std::string shed = fresh.readUntilClose(1000ms);
  EXPECT_EQ(shed.rfind("HTTP/1.1 503 ", 0), 0u) << shed;
  EXPECT_NE(shed.find("Retry-After: 1\r\n"), std::string::npos) << shed;
}

TEST(HttpFairness, AtTheCapTheOldestIdleConnectionIsShedAndBusyOnesAreKept) {
  ServerOptions options = testOptions();
  options.maxConnections = 3;
  TestServer server(options);
  Connection idle(server.port(), 2000ms, 0, "127.0.0.2");
  ASSERT_TRUE(idle.send(getRequest("/first")));
  ASSERT_TRUE(idle.read()); // now an idle keep-alive connection
  Connection busy(server.port(), 2000ms, 0, "127.0.0.3");
  ASSERT_TRUE(busy.send(getRequest("/hang")));
  ASSERT_TRUE(eventually([&] { return server.hungCount() == 1; }, 1000ms));
  Connection younger(server.port(), 2000ms, 0, "127.0.0.4");
  ASSERT_TRUE(younger.send(getRequest("/second")));
  ASSERT_TRUE(younger.read());
  ASSERT_EQ(server.server().connections(), 3u);
  const auto response = fetch(server.port(), getRequest("/new"), 2000ms, "127.0.0.5");
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 200);
  EXPECT_EQ(idle.readUntilClose(1000ms), "") << "an idle connection closes without a response";
  EXPECT_FALSE(younger.closedWithin(100ms)) << "the younger idle connection was shed";
  server.releaseHung();
  const auto hung = busy.read();
  ASSERT_TRUE(hung) << "the busy connection was shed";
  EXPECT_EQ(hung->status, 200);
}

TEST(HttpFairness, ARequestKnowsWhenItsClientHasGone) {
  TestServer server;
  Connection leaving(server.port());
  Connection staying(server.port());
  ASSERT_TRUE(leaving.send(getRequest("/hang")));
  ASSERT_TRUE(staying.send(getRequest("/hang")));
  ASSERT_TRUE(eventually([&] { return server.hungCount() == 2; }, 1000ms));
  EXPECT_EQ(server.hungClientsGone(), 0);
  leaving.close(); // e.g. a browser cancelling a tile request
  EXPECT_TRUE(eventually([&] { return server.hungClientsGone() == 1; }, 1000ms));
  std::this_thread::sleep_for(50ms);
  EXPECT_EQ(server.hungClientsGone(), 1) << "the client still waiting is not gone";
  server.releaseHung();
  const auto response = staying.read();
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 200);
}

TEST(HttpFairness, AHeaderTimeoutIsAnswered408ThenClosed) {
  ServerOptions options = testOptions();
  options.headerTimeout = 300ms;
  TestServer server(options);
  Connection connection(server.port());
  ASSERT_TRUE(connection.send("GET / HTTP/1.1\r\nHost: x\r\nX-A: b"));
  const std::string bytes = connection.readUntilClose(2000ms);
  EXPECT_EQ(bytes.rfind("HTTP/1.1 408 ", 0), 0u) << bytes;
  EXPECT_NE(bytes.find("Connection: close\r\n"), std::string::npos) << bytes;
  EXPECT_NE(bytes.find("request header not complete within 300 ms"), std::string::npos) << bytes;
  EXPECT_TRUE(eventually([&] { return server.server().connections() == 0; }, 1000ms));
}

TEST(HttpFairness, AnIdleKeepAliveTimeoutClosesWithoutAResponse) {
  ServerOptions options = testOptions();
  options.idleTimeout = 300ms;
  TestServer server(options);
  Connection connection(server.port());
  ASSERT_TRUE(connection.send(getRequest("/one")));
  ASSERT_TRUE(connection.read());
  EXPECT_EQ(connection.readUntilClose(2000ms), "");
}

} // namespace
} // namespace strahler::http::test
