#include "world_version.h"

#include "strahler/store/world_file.h"

#include <cstdint>

namespace strahler::app {

std::string contentVersion(std::string_view bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes)
    h = (h ^ c) * 1099511628211ull;
  std::string hex(16, '0');
  for (int i = 15; i >= 0; --i, h >>= 4)
    hex[static_cast<std::size_t>(i)] = "0123456789abcdef"[h & 0xF];
  return hex;
}

std::string worldVersion(const construction::WorldData& world) {
  return contentVersion(store::encodeWorld(world));
}

} // namespace strahler::app
