#pragma once

#include "strahler/base/result.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace strahler::http {

/// The peers whose X-Forwarded-* headers the server believes: IPv4 / IPv6 networks. A request
/// from any other address is answered as if those headers were absent.
class TrustedProxies {
public:
  /// An IPv6 address; IPv4 addresses are held IPv4-mapped (::ffff:a.b.c.d).
  using Address = std::array<std::uint8_t, 16>;

  /// Trusts nobody.
  TrustedProxies() = default;

  /// Parses a comma-separated list of "loopback" (127.0.0.0/8 and ::1), "none", addresses and
  /// networks in CIDR form ("10.0.0.0/8", "fd00::/8"); kInvalidInput naming the bad item.
  static base::Result<TrustedProxies> parse(const std::string& list);

  /// True when `address` lies in one of the networks.
  bool contains(const Address& address) const noexcept;

  /// True when no address is trusted.
  bool empty() const noexcept { return networks_.empty(); }

private:
  struct Network {
    Address prefix{};
    int bits = 0; ///< Leading bits of `prefix` that must match, 0..128.
  };
  std::vector<Network> networks_;
};

} // namespace strahler::http
