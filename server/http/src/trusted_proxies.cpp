#include "strahler/http/trusted_proxies.h"

#include <boost/asio/ip/address.hpp>

#include <algorithm>

namespace strahler::http {
namespace {

namespace ip = boost::asio::ip;

base::Error badItem(const std::string& item, const std::string& why) {
  return base::makeError(base::ErrorCode::kInvalidInput,
                         "trusted proxy '" + item.substr(0, 100) + "': " + why);
}

std::string trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos)
    return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

TrustedProxies::Address toAddress(const ip::address& address) {
  if (address.is_v4())
    return ip::make_address_v6(ip::v4_mapped, address.to_v4()).to_bytes();
  return address.to_v6().to_bytes();
}

/// Zeroes the bits of `address` after the first `bits`.
TrustedProxies::Address masked(TrustedProxies::Address address, int bits) {
  for (int i = 0; i < 16; ++i) {
    const int keep = std::clamp(bits - 8 * i, 0, 8);
    address[static_cast<std::size_t>(i)] &= static_cast<std::uint8_t>(0xFF00u >> keep);
  }
  return address;
}

} // namespace

base::Result<TrustedProxies> TrustedProxies::parse(const std::string& list) {
  TrustedProxies out;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string item = trim(list.substr(start, comma - start));
    start = comma + 1;
    if (item.empty())
      return badItem(item, "empty item in the list");
    if (item == "none")
      continue;
    if (item == "loopback") {
      out.networks_.push_back({toAddress(ip::make_address("127.0.0.0")), 96 + 8});
      out.networks_.push_back({toAddress(ip::make_address("::1")), 128});
      continue;
    }
    const std::size_t slash = item.find('/');
    boost::system::error_code ec;
    const ip::address address = ip::make_address(item.substr(0, slash), ec);
    if (ec)
      return badItem(item, "not an IPv4 or IPv6 address");
    const int width = address.is_v4() ? 32 : 128;
    int bits = width;
    if (slash != std::string::npos) {
      const std::string length = item.substr(slash + 1);
      if (length.empty() || length.size() > 3 ||
          length.find_first_not_of("0123456789") != std::string::npos || std::stoi(length) > width)
        return badItem(item, "prefix length must be 0.." + std::to_string(width));
      bits = std::stoi(length);
    }
    bits += 128 - width;
    const Address prefix = toAddress(address);
    if (masked(prefix, bits) != prefix)
      return badItem(item, "the address has bits set beyond the prefix length");
    out.networks_.push_back({prefix, bits});
  }
  return out;
}

bool TrustedProxies::contains(const Address& address) const noexcept {
  return std::any_of(networks_.begin(), networks_.end(),
                     [&](const Network& n) { return masked(address, n.bits) == n.prefix; });
}

} // namespace strahler::http
