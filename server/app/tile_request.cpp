#include "tile_request.h"

#include <charconv>
#include <cstdint>

namespace strahler::app {

std::string tileKey(const TileRequest& request) {
  std::string key;
  char number[24];
  auto append = [&](std::int64_t v) {
    key.append(number, std::to_chars(number, number + sizeof number, v).ptr);
  };
  key.reserve(request.world.size() + 48);
  key.append(request.world)
      .append(request.scheme == tiling::SchemeKind::kLocal ? "|local|" : "|tiles|");
  append(request.tile.z);
  key.push_back('|');
  append(request.tile.x);
  key.push_back('|');
  append(request.tile.y);
  key.push_back('|');
  key.append(canonicalFormatName(request.format)).push_back('|');
  append(request.options.size);
  return key;
}

} // namespace strahler::app
