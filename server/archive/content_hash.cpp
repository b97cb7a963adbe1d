#include "content_hash.h"

namespace strahler::archive {

std::string ContentHash::toHex() const {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out(32, '0');
  for (int i = 0; i < 16; ++i) {
    out[static_cast<std::size_t>(15 - i)] = kDigits[(high >> (4 * i)) & 15];
    out[static_cast<std::size_t>(31 - i)] = kDigits[(low >> (4 * i)) & 15];
  }
  return out;
}

ContentHash hashContent(std::string_view bytes) noexcept {
  // FNV-1a 128: offset basis 0x6c62272e07bb014262b821756295c58d, prime 2^88 + 0x13b.
  __extension__ using U128 = unsigned __int128;
  const U128 prime = (U128{1} << 88) + 0x13b;
  U128 h = (U128{0x6c62272e07bb0142ull} << 64) | U128{0x62b821756295c58dull};
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= prime;
  }
  return {static_cast<std::uint64_t>(h >> 64), static_cast<std::uint64_t>(h)};
}

} // namespace strahler::archive
