#include "public_url.h"

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
    const auto url = parsePublicUrl(in);
    ASSERT_TRUE(url.ok()) << in << ": " << url.error().message;
    EXPECT_EQ(url.value(), out) << in;
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

} // namespace
} // namespace strahler::app
