// Normal traffic: GET, HEAD, OPTIONS, keep-alive, pipelining, handler failures, observer.
#include "access_log.h"
#include "test_client.h"
#include "test_server.h"

#include "strahler/http/http_types.h"

#include <gtest/gtest.h>

namespace strahler::http::test {
namespace {

using namespace std::chrono_literals;

void expectCommonHeaders(const RawResponse& response) {
  EXPECT_EQ(response.header("access-control-allow-origin"), "*");
  EXPECT_EQ(response.header("server"), "strahler");
  EXPECT_NE(response.header("date").find(" GMT"), std::string::npos);
  EXPECT_EQ(response.count("access-control-allow-origin"), 1u);
}

TEST(HttpServer, GetReturnsTheHandlersBodyWithCorsAndContentLength) {
  TestServer server;
  const auto response = fetch(server.port(), getRequest("/hello?x=1"));
  ASSERT_TRUE(response);
  EXPECT_EQ(response->version, "HTTP/1.1");
  EXPECT_EQ(response->status, 200);
  EXPECT_EQ(response->body, "/hello?x=1");
  EXPECT_EQ(response->header("content-length"), "10");
  EXPECT_EQ(response->header("content-type"), "text/plain");
  EXPECT_EQ(response->header("etag"), "\"v1\"");
  EXPECT_EQ(response->header("x-head"), "0");
  EXPECT_EQ(response->header("x-method"), "GET");
  expectCommonHeaders(*response);
}

TEST(HttpServer, HeadersReachTheHandlerWithLowerCaseNames) {
  TestServer server;
  const auto response = fetch(server.port(), getRequest("/x-test", "X-TeSt: hello\r\n"));
  ASSERT_TRUE(response);
  EXPECT_EQ(response->body, "hello");
}

TEST(HttpServer, HeadSendsTheHeadersOfGetWithoutTheBody) {
  TestServer server;
  Connection connection(server.port());
  // HEAD then GET in one write: if HEAD leaked a body, the GET's status line would not follow.
  ASSERT_TRUE(connection.send("HEAD /big HTTP/1.1\r\nHost: t\r\n\r\n" + getRequest("/big")));
  const auto head = connection.read(/*head=*/true);
  const auto get = connection.read();
  ASSERT_TRUE(head && get);
  EXPECT_EQ(head->status, 200);
  EXPECT_EQ(head->header("content-length"), "1048576");
  EXPECT_EQ(get->body.size(), 1048576u);
  auto withoutDate = [](std::vector<std::pair<std::string, std::string>> headers) {
    std::erase_if(headers, [](const auto& field) { return field.first == "date"; });
    return headers;
  };
  EXPECT_EQ(withoutDate(head->headers), withoutDate(get->headers));
}

/// `bytes` with every Date value replaced by "-".
std::string withoutDateValues(std::string bytes) {
  for (std::size_t at = bytes.find("\r\nDate: "); at != std::string::npos;
       at = bytes.find("\r\nDate: ", at + 1)) {
    const std::size_t value = at + 8;
    bytes.replace(value, bytes.find("\r\n", value) - value, "-");
  }
  return bytes;
}

TEST(HttpServer, PreparedFieldsGoOutByteForByteAsTheFieldsTheyWereMadeFrom) {
  TestServer server;
  // Each case: request line and headers, then a second request that closes the connection,
  // so that everything the server sends can be read to the end.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"GET ", " HTTP/1.1\r\nHost: t\r\n\r\n"},
      {"HEAD ", " HTTP/1.1\r\nHost: t\r\n\r\n"},
      {"GET ", " HTTP/1.0\r\nConnection: keep-alive\r\n\r\n"},
      {"GET ", " HTTP/1.0\r\n\r\n"},
  };
  for (const char* status : {"200", "304", "404", "503"}) {
    for (const auto& [method, rest] : cases) {
      std::string sent[2];
      for (int prepared = 0; prepared < 2; ++prepared) {
        const std::string target = std::string("/fields/") + status + (prepared ? "?prepared" : "");
        Connection connection(server.port());
        ASSERT_TRUE(connection.send(method + target + rest + method + target +
                                    " HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n"));
        sent[prepared] = connection.readUntilClose(2000ms);
      }
      EXPECT_EQ(withoutDateValues(sent[1]), withoutDateValues(sent[0])) << method << rest;
      EXPECT_NE(sent[0].find("HTTP/1."), std::string::npos);
      EXPECT_NE(sent[0].find("X-Padded: padded value\r\n"), std::string::npos) << sent[0];
      EXPECT_EQ(sent[0].find("Injected"), std::string::npos) << sent[0];
      EXPECT_EQ(sent[0].find("not this one"), std::string::npos) << sent[0];
    }
  }
}

TEST(HttpServer, HeadIsForwardedAsGetWithTheHeadFlag) {
  TestServer server;
  const auto response = fetch(server.port(), "HEAD /abc HTTP/1.1\r\nHost: t\r\n\r\n");
  ASSERT_TRUE(response);
  EXPECT_EQ(response->header("x-head"), "1");
  EXPECT_EQ(response->header("x-method"), "GET");
  EXPECT_EQ(response->header("content-length"), "4");
}

TEST(HttpServer, OptionsIsAPreflightWithoutBody) {
  TestServer server;
  Connection connection(server.port());
  ASSERT_TRUE(connection.send("OPTIONS /worlds/a/tiles/0/0/0.png HTTP/1.1\r\nHost: t\r\n"
                              "Origin: https://example.org\r\n"
                              "Access-Control-Request-Method: GET\r\n\r\n" +
                              getRequest("/after")));
  const auto preflight = connection.read();
  ASSERT_TRUE(preflight);
  EXPECT_EQ(preflight->status, 204);
  EXPECT_EQ(preflight->header("access-control-allow-methods"), "GET, HEAD, OPTIONS");
  EXPECT_EQ(preflight->header("access-control-allow-headers"), "*");
  EXPECT_EQ(preflight->header("access-control-max-age"), "86400");
  EXPECT_EQ(preflight->count("content-length"), 0u);
  expectCommonHeaders(*preflight);
  const auto after = connection.read(); // keep-alive continues, nothing was left unread
  ASSERT_TRUE(after);
  EXPECT_EQ(after->body, "/after");
  EXPECT_EQ(server.handlerCalls(), 1);
  const auto star = fetch(server.port(), "OPTIONS * HTTP/1.1\r\nHost: t\r\n\r\n");
  ASSERT_TRUE(star);
  EXPECT_EQ(star->status, 204);
}

TEST(HttpServer, KeepAliveServesManyRequestsOnOneConnection) {
  TestServer server;
  Connection connection(server.port());
  for (int i = 0; i < 10; ++i) {
    const std::string target = "/k" + std::to_string(i);
    ASSERT_TRUE(connection.send(getRequest(target)));
    const auto response = connection.read();
    ASSERT_TRUE(response) << i;
    EXPECT_EQ(response->body, target);
    EXPECT_EQ(response->count("connection"), 0u);
  }
  EXPECT_EQ(server.server().connections(), 1u);
}

TEST(HttpServer, Http10WithoutHostIsServedAndClosedUnlessKeepAliveIsAsked) {
  TestServer server;
  Connection plain(server.port());
  ASSERT_TRUE(plain.send("GET /old HTTP/1.0\r\n\r\n"));
  const auto response = plain.read();
  ASSERT_TRUE(response);
  EXPECT_EQ(response->version, "HTTP/1.0");
  EXPECT_EQ(response->status, 200);
  EXPECT_TRUE(plain.closedWithin(1000ms));

  Connection keepAlive(server.port());
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(keepAlive.send("GET /old HTTP/1.0\r\nConnection: keep-alive\r\n\r\n"));
    const auto again = keepAlive.read();
    ASSERT_TRUE(again) << i;
    EXPECT_EQ(again->header("connection"), "keep-alive");
  }
}

TEST(HttpServer, ConnectionCloseRequestIsAnsweredThenClosed) {
  TestServer server;
  Connection connection(server.port());
  ASSERT_TRUE(
      connection.send(getRequest("/bye", "Connection: close\r\n") + getRequest("/ignored")));
  const auto response = connection.read();
  ASSERT_TRUE(response);
  EXPECT_EQ(response->header("connection"), "close");
  EXPECT_TRUE(connection.closedWithin(1000ms));
}

TEST(HttpServer, HandlerCanAskToCloseTheConnection) {
  TestServer server;
  Connection connection(server.port());
  ASSERT_TRUE(connection.send(getRequest("/close")));
  const auto response = connection.read();
  ASSERT_TRUE(response);
  EXPECT_EQ(response->body, "bye");
  EXPECT_EQ(response->header("connection"), "close");
  EXPECT_TRUE(connection.closedWithin(1000ms));
}

TEST(HttpServer, PipelinedResponsesComeBackInRequestOrder) {
  TestServer server;
  Connection connection(server.port());
  const std::vector<std::string> targets = {"/slow-a", "/b", "/slow-c", "/d", "/e"};
  std::string batch;
  for (const auto& target : targets)
    batch += getRequest(target);
  ASSERT_TRUE(connection.send(batch));
  for (const auto& target : targets) {
    const auto response = connection.read();
    ASSERT_TRUE(response) << target;
    EXPECT_EQ(response->body, target);
  }
  // The two slow requests ran concurrently (counted, not timed: the sanitized run is slow).
  EXPECT_EQ(server.peakSlowInFlight(), 2);
}

TEST(HttpServer, PipeliningCapPausesReading) {
  ServerOptions options = testOptions();
  options.maxPipelined = 2;
  TestServer server(options);
  Connection connection(server.port());
  std::string batch;
  for (int i = 0; i < 6; ++i)
    batch += getRequest("/slow" + std::to_string(i));
  ASSERT_TRUE(connection.send(batch));
  for (int i = 0; i < 6; ++i) {
    const auto response = connection.read();
    ASSERT_TRUE(response) << i;
    EXPECT_EQ(response->body, "/slow" + std::to_string(i));
  }
  // At most two slow requests were in flight at a time (counted, not timed).
  EXPECT_EQ(server.peakSlowInFlight(), 2);
}

TEST(HttpServer, ThrowingHandlerGets500AndTheServerCarriesOn) {
  TestServer server;
  Connection connection(server.port());
  ASSERT_TRUE(connection.send(getRequest("/throw") + getRequest("/fine")));
  const auto failed = connection.read();
  ASSERT_TRUE(failed);
  EXPECT_EQ(failed->status, 500);
  EXPECT_EQ(failed->header("content-type"), "application/json");
  EXPECT_EQ(failed->header("cache-control"), "no-store");
  EXPECT_EQ(failed->body, R"({"error": "internal server error"})");
  const auto fine = connection.read();
  ASSERT_TRUE(fine);
  EXPECT_EQ(fine->status, 200);
}

#ifndef NDEBUG
TEST(HttpServerDeathTest, CallingDoneTwiceAssertsInDebugBuilds) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(
      {
        TestServer server;
        fetch(server.port(), getRequest("/twice"));
      },
      "called done twice");
}
#else
TEST(HttpServer, CallingDoneTwiceIsIgnoredInReleaseBuilds) {
  TestServer server;
  Connection connection(server.port());
  ASSERT_TRUE(connection.send(getRequest("/twice") + getRequest("/next")));
  const auto first = connection.read();
  const auto next = connection.read();
  ASSERT_TRUE(first && next);
  EXPECT_EQ(first->body, "first");
  EXPECT_EQ(next->body, "/next");
}
#endif

TEST(HttpServer, HandlerStatusesAndHeadersAreSanitised) {
  TestServer server;
  const auto invalid = fetch(server.port(), getRequest("/status/42"));
  ASSERT_TRUE(invalid);
  EXPECT_EQ(invalid->status, 500);
  const auto unavailable = fetch(server.port(), getRequest("/status/503"));
  ASSERT_TRUE(unavailable);
  EXPECT_EQ(unavailable->status, 503);
  EXPECT_EQ(unavailable->header("cache-control"), "no-store");
  const auto evil = fetch(server.port(), getRequest("/evil"));
  ASSERT_TRUE(evil);
  EXPECT_EQ(evil->count("x-evil"), 0u);
  EXPECT_EQ(evil->count("injected"), 0u);
  EXPECT_EQ(evil->header("content-length"), "4");
  EXPECT_EQ(evil->body, "evil");
}

TEST(HttpServer, ObserverSeesEveryRequestWithItsRoute) {
  TestServer server;
  Connection connection(server.port());
  ASSERT_TRUE(connection.send(getRequest("/abc") + "OPTIONS / HTTP/1.1\r\nHost: t\r\n\r\n" +
                              "POST / HTTP/1.1\r\nHost: t\r\n\r\n" +
                              "HEAD /abcd HTTP/1.1\r\nHost: t\r\n\r\n"));
  ASSERT_TRUE(connection.read());
  ASSERT_TRUE(connection.read());
  ASSERT_TRUE(connection.read());
  ASSERT_TRUE(connection.read(/*head=*/true));
  // The observer runs once the write completed, possibly just after the client read it.
  ASSERT_TRUE(eventually([&] { return server.observations().size() == 4; }, 1000ms));
  const auto seen = server.observations();
  EXPECT_EQ(seen[0].route, "echo");
  EXPECT_EQ(seen[0].status, 200);
  EXPECT_EQ(seen[0].bytes, 4u);
  EXPECT_EQ(seen[1].route, "options");
  EXPECT_EQ(seen[1].status, 204);
  EXPECT_EQ(seen[2].route, "error");
  EXPECT_EQ(seen[2].status, 405);
  EXPECT_EQ(seen[3].status, 200);
  EXPECT_EQ(seen[3].bytes, 0u); // HEAD sends no body bytes
}

TEST(HttpServer, SixtyFourClientsTimesTwentyRequestsAllSucceed) {
  TestServer server;
  std::atomic<int> ok{0};
  std::vector<std::thread> clients;
  for (int c = 0; c < 64; ++c) {
    clients.emplace_back([&, c] {
      Connection connection(server.port());
      for (int i = 0; i < 20; ++i) {
        const std::string target = "/c" + std::to_string(c) + "/" + std::to_string(i);
        if (!connection.send(getRequest(target)))
          return;
        const auto response = connection.read();
        if (response && response->status == 200 && response->body == target)
          ++ok;
      }
    });
  }
  for (auto& client : clients)
    client.join();
  EXPECT_EQ(ok.load(), 64 * 20);
}

TEST(ErrorResponse, IsJsonWithEscapedMessage) {
  const Response response = errorResponse(404, "no \"tile\" at \\ \x01 \xff");
  EXPECT_EQ(response.status, 404);
  EXPECT_EQ(response.body, "{\"error\": \"no \\\"tile\\\" at \\\\ \\u0001 \xEF\xBF\xBD\"}");
  EXPECT_EQ(response.route, "error");
  EXPECT_EQ(response.headers.size(), 1u);
  const Response internal = errorResponse(500, "é");
  EXPECT_EQ(internal.body, "{\"error\": \"é\"}");
  EXPECT_EQ(internal.headers.size(), 2u);
}

TEST(AccessLog, LineIsEscapedAndTruncated) {
  EXPECT_EQ(detail::formatAccessLine("GET", "/a b\n\x1b[31m", 200, 12, 1.26),
            "GET /a\\x20b\\x0a\\x1b[31m 200 12 1.3");
  const std::string longTarget(300, 'x');
  const std::string line = detail::formatAccessLine("GET", longTarget, 414, 0, 0.0);
  EXPECT_EQ(line, "GET " + std::string(200, 'x') + "... 414 0 0.0");
  EXPECT_EQ(detail::formatAccessLine("", "", 400, 5, 0.04), "- - 400 5 0.0");
}

} // namespace
} // namespace strahler::http::test
