#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace strahler::archive {

/// A 128-bit FNV-1a digest of a tile's bytes: the dedup key of both writers (as go-pmtiles
/// does). Two different tiles share one with probability ~2⁻¹²⁸.
struct ContentHash {
  std::uint64_t high = 0;
  std::uint64_t low = 0;

  friend bool operator==(const ContentHash&, const ContentHash&) = default;
  /// 32 lower-case hex digits.
  std::string toHex() const;
};

/// The FNV-1a 128 digest of `bytes`.
ContentHash hashContent(std::string_view bytes) noexcept;

/// Hash functor for unordered containers keyed by ContentHash.
struct ContentHashHasher {
  std::size_t operator()(const ContentHash& h) const noexcept {
    return static_cast<std::size_t>(h.low ^ (h.high * 0x9e3779b97f4a7c15ull));
  }
};

} // namespace strahler::archive
