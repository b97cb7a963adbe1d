#include "public_url.h"
#include "result_matchers.h"

#include <gtest/gtest.h>

namespace strahler::app {
namespace {

TEST(PublicUrl, AcceptsOriginsWithPortAndPathPrefixInOneSpelling) {
  const std::pair<const char*, const char*> good[] = {
      {"http://localhost:8080", "http://localhost:8080"},
      {"https://Tiles.Example.org/", "https://tiles.example.org"},
      {"HTTPS://tiles.example.org/terrain/v1/", "https://tiles.example.org/terrain/v1"},
      {"http://10.0.0.5:65535/a%20b", "http://10.0.0.5:65535/a%20b"},
      {"http://[::1]:8080/x", "http://[::1]:8080/x"},
      {"http://[2001:DB8::1]", "http://[2001:db8::1]"}};
  for (const auto& [in, out] : good) {
    STRAHLER_ASSIGN_OR_ASSERT(const auto url, parsePublicUrl(in));
    EXPECT_EQ(url, out) << in;
  }
}

TEST(PublicUrl, RefusesAnythingElseSayingWhy) {
  const std::pair<const char*, const char*> bad[] = {
      {"tiles.example.org", "must start with http:// or https://"},
      {"ftp://tiles.example.org", "scheme must be http or https, not 'ftp'"},
      {"http://", "has no host"},
      {"http:///path", "has no host"},
      {"http://:8080", "has no host"},
      {"http://user:pw@example.org", "user info is not allowed"},
      {"http://example.org/?a=1", "a query or fragment is not allowed"},
      {"http://example.org#top", "a query or fragment is not allowed"},
      {"http://example.org:0", "port must be a number in 1..65535"},
      {"http://example.org:65536", "port must be a number in 1..65535"},
      {"http://example.org:", "port must be a number in 1..65535"},
      {"http://example.org:80x", "port must be a number in 1..65535"},
      {"http://exa mple.org", "'exa mple.org' is not a host name or address"},
      {"http://evil.example\\@x", "user info is not allowed"},
      {"http://-a.org", "'-a.org' is not a host name or address"},
      {"http://[::1", "unclosed '[' in the host"},
      {"http://[zz]:80", "'[zz]' is not an IPv6 address"},
      {"http://[::1]x", "expected ':' and a port after the IPv6 address"},
      {"http://example.org/a b", "the path may hold only URL path characters"},
      {"http://example.org/a\"b", "the path may hold only URL path characters"}};
  for (const auto& [in, why] : bad) {
    const auto url = parsePublicUrl(in);
    ASSERT_FALSE(url.ok()) << in;
    EXPECT_EQ(url.error().message, std::string("--public-url '") + in + "': " + why) << in;
  }
}

/// A request that arrived on 127.0.0.1:8080 with `headers`, from a trusted proxy or not.
http::Request requestWith(bool trusted, std::vector<std::pair<std::string, std::string>> headers) {
  http::Request r;
  r.localAddress = "127.0.0.1:8080";
  r.fromTrustedProxy = trusted;
  r.headers = std::move(headers);
  r.headers.emplace_back("host", "evil.example");
  return r;
}

TEST(RequestOrigin, PublicUrlThenTrustedForwardedHeadersThenTheLocalAddress) {
  const auto proxied = requestWith(true, {{"x-forwarded-proto", "HTTPS, http"},
                                          {"x-forwarded-host", " Maps.Example.org:8443 "}});
  EXPECT_EQ(test_support::valueOf(requestOrigin("https://cdn.example.com/p", proxied)),
            "https://cdn.example.com/p");
  EXPECT_EQ(test_support::valueOf(requestOrigin("", proxied)), "https://maps.example.org:8443");
  EXPECT_EQ(test_support::valueOf(requestOrigin("", requestWith(true, {}))),
            "http://127.0.0.1:8080");
  EXPECT_EQ(
      test_support::valueOf(requestOrigin("", requestWith(true, {{"x-forwarded-proto", "https"}}))),
      "https://127.0.0.1:8080");
  EXPECT_EQ(test_support::valueOf(
                requestOrigin("", requestWith(true, {{"x-forwarded-host", "[2001:DB8::1]"}}))),
            "http://[2001:db8::1]");
  auto untrusted = proxied;
  untrusted.fromTrustedProxy = false;
  EXPECT_EQ(test_support::valueOf(requestOrigin("", untrusted)), "http://127.0.0.1:8080");
}

TEST(RequestOrigin, RefusesMalformedForwardedHeadersNamingThem) {
  const std::pair<std::pair<const char*, const char*>, const char*> bad[] = {
      {{"x-forwarded-proto", "wss"}, "X-Forwarded-Proto 'wss': must be http or https"},
      {{"x-forwarded-host", "a b"}, "X-Forwarded-Host 'a b': 'a b' is not a host name or address"},
      {{"x-forwarded-host", "h:0"}, "X-Forwarded-Host 'h:0': port must be a number in 1..65535"},
      {{"x-forwarded-host", "[::1"}, "X-Forwarded-Host '[::1': unclosed '[' in the host"}};
  for (const auto& [header, message] : bad) {
    const auto origin = requestOrigin("", requestWith(true, {{header.first, header.second}}));
    ASSERT_FALSE(origin.ok()) << header.second;
    EXPECT_EQ(origin.error().message, message);
  }
}

} // namespace
} // namespace strahler::app
