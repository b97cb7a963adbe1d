// Requests the server must refuse itself, each with its exact status; the server survives all.
#include "test_client.h"
#include "test_server.h"

#include <gtest/gtest.h>

#include <ostream>

namespace strahler::http::test {
namespace {

using namespace std::chrono_literals;

struct BadRequest {
  const char* name;
  std::string bytes;
  int status;
  bool closes; ///< The server closes the connection after answering.
};

std::ostream& operator<<(std::ostream& out, const BadRequest& bad) {
  return out << bad.name;
}

std::string withHost(std::string_view requestLine, std::string_view headers = {}) {
  return std::string(requestLine) + "\r\nHost: t\r\n" + std::string(headers) + "\r\n";
}

std::vector<BadRequest> badRequests() {
  const std::string target3000 = "/" + std::string(2999, 'a');
  const std::string target9000 = "/" + std::string(8999, 'a');
  std::string bigHeaders;
  for (int i = 0; i < 100; ++i)
    bigHeaders += "X-Filler-" + std::to_string(i) + ": " + std::string(100, 'f') + "\r\n";
  return {
      {"Post", withHost("POST /x HTTP/1.1", "Content-Length: 0\r\n"), 405, false},
      {"PostWithBody", withHost("POST /x HTTP/1.1", "Content-Length: 5\r\n") + "hello", 405, true},
      {"Put", withHost("PUT /x HTTP/1.1"), 405, false},
      {"Delete", withHost("DELETE /x HTTP/1.1"), 405, false},
      {"Patch", withHost("PATCH /x HTTP/1.1"), 405, false},
      {"Trace", withHost("TRACE /x HTTP/1.1"), 405, false},
      {"Connect", withHost("CONNECT example.org:443 HTTP/1.1"), 405, false},
      {"LowerCaseMethod", withHost("get / HTTP/1.1"), 405, false},
      {"GarbageLine", "HELLO\r\n\r\n", 400, true},
      {"TlsHandshake", std::string("\x16\x03\x01\x02\x00\x01\x00\x01\xfc\x03\x03", 11) + "\r\n\r\n",
       400, true},
      {"MissingVersion", "GET /\r\n\r\n", 400, true},
      {"LowerCaseVersion", withHost("GET / http/1.1"), 400, true},
      {"ExtraSpaceInLine", withHost("GET /a b HTTP/1.1"), 400, true},
      {"Http20", withHost("GET / HTTP/2.0"), 505, true},
      {"Http12", withHost("GET / HTTP/1.2"), 505, true},
      {"Http2Preface", "PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n", 505, true},
      {"Target3000", withHost("GET " + target3000 + " HTTP/1.1"), 414, false},
      {"Target9000", withHost("GET " + target9000 + " HTTP/1.1"), 414, true},
      {"Headers10K", withHost("GET / HTTP/1.1", bigHeaders), 431, true},
      {"OneHeader10K", withHost("GET / HTTP/1.1", "X-Big: " + std::string(10000, 'v') + "\r\n"),
       431, true},
      {"GetWithBody", withHost("GET / HTTP/1.1", "Content-Length: 5\r\n") + "hello", 400, true},
      {"HeadWithBody", withHost("HEAD / HTTP/1.1", "Content-Length: 1\r\n") + "x", 400, true},
      {"TeGzip",
       withHost("GET / HTTP/1.1", "Transfer-Encoding: gzip\r\n") +
           "GET /smuggled HTTP/1.1\r\nHost: t\r\n\r\n",
       400, true},
      {"TeGzipThenLength",
       withHost("GET / HTTP/1.1", "Transfer-Encoding: gzip\r\nContent-Length: 5\r\n") + "hello",
       400, true},
      {"LengthThenTeGzip",
       withHost("GET / HTTP/1.1", "Content-Length: 5\r\nTransfer-Encoding: gzip\r\n") + "hello",
       400, true},
      {"TeGzipChunked",
       withHost("GET / HTTP/1.1", "Transfer-Encoding: gzip, chunked\r\n") + "0\r\n\r\n", 400, true},
      {"TeChunkedOnGet", withHost("GET / HTTP/1.1", "Transfer-Encoding: chunked\r\n") + "0\r\n\r\n",
       400, true},
      {"TeTwice",
       withHost("GET / HTTP/1.1", "Transfer-Encoding: chunked\r\nTransfer-Encoding: chunked\r\n") +
           "0\r\n\r\n",
       400, true},
      {"Http11WithoutHost", "GET / HTTP/1.1\r\n\r\n", 400, true},
      {"TwoHosts", withHost("GET / HTTP/1.1", "Host: u\r\n"), 400, true},
      {"BareLf", "GET / HTTP/1.1\nHost: t\n\n", 400, true},
      {"BareLfInHeaders", "GET / HTTP/1.1\r\nHost: t\nX-A: b\r\n\r\n", 400, true},
      {"NulInTarget", withHost(std::string("GET /a\0b HTTP/1.1", 17)), 400, true},
      {"DelInTarget",
       withHost("GET /a\x7f"
                "b HTTP/1.1"),
       400, true},
      {"AbsurdContentLength",
       withHost("GET / HTTP/1.1", "Content-Length: 99999999999999999999999\r\n"), 400, true},
      {"NegativeContentLength", withHost("GET / HTTP/1.1", "Content-Length: -1\r\n"), 400, true},
      {"ConflictingContentLengths",
       withHost("GET / HTTP/1.1", "Content-Length: 1\r\nContent-Length: 2\r\n"), 400, true},
      {"HeaderWithoutColon", withHost("GET / HTTP/1.1", "X-Broken\r\n"), 400, true},
      {"SpaceBeforeColon", withHost("GET / HTTP/1.1", "X-Broken : 1\r\n"), 400, true},
      {"ControlCharInValue", withHost("GET / HTTP/1.1", "X-Broken: a\x01z\r\n"), 400, true},
      {"AbsoluteFormTarget", withHost("GET http://t/ HTTP/1.1"), 400, true},
      {"AsteriskTargetOnGet", withHost("GET * HTTP/1.1"), 400, true},
  };
}

class BadRequestTest : public ::testing::TestWithParam<BadRequest> {
protected:
  static void SetUpTestSuite() { server_ = new TestServer(); }
  static void TearDownTestSuite() {
    delete server_;
    server_ = nullptr;
  }
  static TestServer* server_;
};

TestServer* BadRequestTest::server_ = nullptr;

TEST_P(BadRequestTest, GetsItsStatusAndTheServerStillAnswers) {
  const BadRequest& bad = GetParam();
  Connection connection(server_->port());
  ASSERT_TRUE(connection.send(bad.bytes));
  const bool head = bad.bytes.rfind("HEAD ", 0) == 0; // the answer to HEAD has no body
  const auto response = connection.read(head);
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, bad.status);
  EXPECT_EQ(response->header("content-type"), "application/json");
  if (!head) {
    EXPECT_EQ(response->body.rfind("{\"error\": \"", 0), 0u) << response->body;
  }
  EXPECT_EQ(response->header("access-control-allow-origin"), "*");
  if (bad.status == 405) {
    EXPECT_EQ(response->header("allow"), "GET, HEAD, OPTIONS");
  }
  if (bad.closes) {
    EXPECT_EQ(response->header("connection"), "close");
    EXPECT_TRUE(connection.closedWithin(1000ms));
  } else {
    ASSERT_TRUE(connection.send(getRequest("/same-connection")));
    const auto next = connection.read();
    ASSERT_TRUE(next);
    EXPECT_EQ(next->body, "/same-connection");
  }
  const auto fresh = fetch(server_->port(), getRequest("/fresh"));
  ASSERT_TRUE(fresh);
  EXPECT_EQ(fresh->status, 200);
}

INSTANTIATE_TEST_SUITE_P(HttpServer, BadRequestTest, ::testing::ValuesIn(badRequests()),
                         [](const auto& test) { return std::string(test.param.name); });

TEST(HttpServer, EveryBadRequestClosesTheConnectionEvenPipelined) {
  TestServer server;
  // The server's own 400 (absolute form) and the handler's 400 (its answer to a bad path) close
  // alike; a request pipelined behind them is never handled.
  const std::pair<std::string, int> cases[] = {{withHost("GET http://t/first HTTP/1.1"), 0},
                                               {getRequest("/status/400"), 1}};
  for (const auto& [first, calls] : cases) {
    const int callsBefore = server.handlerCalls();
    Connection connection(server.port());
    ASSERT_TRUE(connection.send(first + getRequest("/pipelined")));
    const auto response = connection.read();
    ASSERT_TRUE(response);
    EXPECT_EQ(response->status, 400) << first;
    EXPECT_EQ(response->header("connection"), "close") << first;
    EXPECT_TRUE(connection.closedWithin(1000ms)) << first;
    EXPECT_EQ(server.handlerCalls() - callsBefore, calls) << first;
  }
  // Other handler errors keep the connection.
  Connection connection(server.port());
  ASSERT_TRUE(connection.send(getRequest("/status/404")));
  const auto notFound = connection.read();
  ASSERT_TRUE(notFound);
  EXPECT_EQ(notFound->status, 404);
  ASSERT_TRUE(connection.send(getRequest("/same-connection")));
  const auto next = connection.read();
  ASSERT_TRUE(next);
  EXPECT_EQ(next->body, "/same-connection");
}

TEST(HttpServer, SmuggledRequestAfterGzipTransferEncodingIsNeverHandled) {
  TestServer server;
  Connection connection(server.port());
  ASSERT_TRUE(connection.send(withHost("GET /first HTTP/1.1", "Transfer-Encoding: gzip\r\n") +
                              getRequest("/smuggled")));
  const auto response = connection.read();
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 400);
  EXPECT_TRUE(connection.closedWithin(1000ms));
  EXPECT_EQ(server.handlerCalls(), 0);
}

TEST(HttpServer, ErrorMessagesNameTheProblem) {
  TestServer server;
  const auto gzip = fetch(server.port(), withHost("GET / HTTP/1.1", "Transfer-Encoding: gzip\r\n"));
  ASSERT_TRUE(gzip);
  EXPECT_EQ(gzip->body, R"({"error": "Transfer-Encoding 'gzip' is not supported"})");
  const auto version = fetch(server.port(), withHost("GET / HTTP/2.0"));
  ASSERT_TRUE(version);
  EXPECT_EQ(version->body, R"({"error": "HTTP/2.0 is not supported; use HTTP/1.1"})");
  const auto header = fetch(
      server.port(), withHost("GET / HTTP/1.1", "X-Big: " + std::string(9000, 'v') + " x\r\n"));
  ASSERT_TRUE(header);
  EXPECT_EQ(header->body, R"({"error": "request header block exceeds 8192 bytes"})");
  const auto target =
      fetch(server.port(), withHost("GET /" + std::string(9000, 't') + " HTTP/1.1"));
  ASSERT_TRUE(target);
  EXPECT_EQ(target->body, R"({"error": "request target exceeds 2048 bytes"})");
  const auto method = fetch(server.port(), withHost("DELETE / HTTP/1.1"));
  ASSERT_TRUE(method);
  EXPECT_EQ(method->body,
            R"({"error": "method 'DELETE' is not allowed; use GET, HEAD or OPTIONS"})");
}

} // namespace
} // namespace strahler::http::test
