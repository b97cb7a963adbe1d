// Which peers' X-Forwarded-* headers the server believes.
#include "result_matchers.h"
#include "strahler/http/trusted_proxies.h"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <cstring>

namespace strahler::http {
namespace {

/// `text` (an IPv4 or IPv6 address) as TrustedProxies holds addresses.
TrustedProxies::Address address(const std::string& text) {
  TrustedProxies::Address out{};
  in_addr v4{};
  if (inet_pton(AF_INET, text.c_str(), &v4) == 1) {
    out[10] = out[11] = 0xFF;
    std::memcpy(out.data() + 12, &v4, 4);
  } else {
    EXPECT_EQ(inet_pton(AF_INET6, text.c_str(), out.data()), 1) << text;
  }
  return out;
}

TEST(TrustedProxies, LoopbackMeansBothFamiliesLoopbackNetworks) {
  STRAHLER_ASSIGN_OR_ASSERT(const auto trusted, TrustedProxies::parse("loopback"));
  for (const char* in : {"127.0.0.1", "127.255.0.9", "::1", "::ffff:127.0.0.1"})
    EXPECT_TRUE(trusted.contains(address(in))) << in;
  for (const char* in : {"128.0.0.1", "10.0.0.1", "::2", "fe80::1", "::"})
    EXPECT_FALSE(trusted.contains(address(in))) << in;
}

TEST(TrustedProxies, NetworksMatchTheirPrefixOnly) {
  const auto trusted = test_support::valueOf(
      TrustedProxies::parse("172.16.0.0/12, 192.168.1.7,fd00::/8,0.0.0.0/32"));
  for (const char* in : {"172.16.0.1", "172.31.255.255", "192.168.1.7", "fd12:3456::1", "0.0.0.0"})
    EXPECT_TRUE(trusted.contains(address(in))) << in;
  for (const char* in : {"172.32.0.1", "172.15.255.255", "192.168.1.8", "fe00::1", "127.0.0.1"})
    EXPECT_FALSE(trusted.contains(address(in))) << in;
  EXPECT_TRUE(
      test_support::valueOf(TrustedProxies::parse("0.0.0.0/0")).contains(address("8.8.8.8")));
  EXPECT_FALSE(
      test_support::valueOf(TrustedProxies::parse("0.0.0.0/0")).contains(address("2001:db8::1")))
      << "an IPv4 network holds IPv4 addresses only";
  EXPECT_TRUE(
      test_support::valueOf(TrustedProxies::parse("::/0")).contains(address("2001:db8::1")));
}

TEST(TrustedProxies, NoneTrustsNobody) {
  EXPECT_TRUE(test_support::valueOf(TrustedProxies::parse("none")).empty());
  EXPECT_TRUE(TrustedProxies().empty());
  EXPECT_FALSE(TrustedProxies().contains(address("127.0.0.1")));
}

TEST(TrustedProxies, RefusesBadItemsSayingWhich) {
  const std::pair<const char*, const char*> bad[] = {
      {"", "trusted proxy '': empty item in the list"},
      {"loopback,", "trusted proxy '': empty item in the list"},
      {"localhost", "trusted proxy 'localhost': not an IPv4 or IPv6 address"},
      {"10.0.0.0/33", "trusted proxy '10.0.0.0/33': prefix length must be 0..32"},
      {"fd00::/129", "trusted proxy 'fd00::/129': prefix length must be 0..128"},
      {"10.0.0.0/", "trusted proxy '10.0.0.0/': prefix length must be 0..32"},
      {"10.0.0.0/-1", "trusted proxy '10.0.0.0/-1': prefix length must be 0..32"},
      {"10.0.0.1/8",
       "trusted proxy '10.0.0.1/8': the address has bits set beyond the prefix length"},
      {"1.2.3.4.5", "trusted proxy '1.2.3.4.5': not an IPv4 or IPv6 address"}};
  for (const auto& [in, message] : bad) {
    const auto parsed = TrustedProxies::parse(in);
    ASSERT_FALSE(parsed.ok()) << in;
    EXPECT_EQ(parsed.error().message, message) << in;
  }
}

} // namespace
} // namespace strahler::http
