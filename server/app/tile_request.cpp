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
  key.append(request.world);
  switch (request.scheme) {
  case tiling::SchemeKind::kLocal:
    key.append("|local|");
    break;
  case tiling::SchemeKind::kGeographic:
    key.append("|cesium|");
    break;
  case tiling::SchemeKind::kWebMercator:
    key.append("|tiles|");
    break;
  }
  append(request.tile.z);
  key.push_back('|');
  append(request.tile.x);
  key.push_back('|');
  append(request.tile.y);
  key.push_back('|');
  key.append(canonicalFormatName(request.format)).push_back('|');
  append(request.options.size);
  if (request.kind() == TileKind::kTerrain) {
    key.push_back('|');
    append(request.options.extensions);
    key.append(request.options.gzip ? "|gz" : "|id");
  }
  if (request.kind() == TileKind::kVector || request.kind() == TileKind::kVegetation)
    key.append(request.options.gzip ? "|gz" : "|id");
  if (request.kind() == TileKind::kLayer) {
    const LayerOptions& layer = request.options.layer;
    key.push_back('|');
    key.append(kLayerNames[static_cast<std::size_t>(layer.name)]);
    if (layer.name == LayerName::kVegetation) {
      key.push_back('|');
      append(layer.species);
    }
    if (layer.name == LayerName::kHillshade)
      for (const double degrees : {layer.azimuthDeg, layer.altitudeDeg}) {
        key.push_back('|'); // shortest round-trip spelling: one per value
        key.append(number, std::to_chars(number, number + sizeof number, degrees).ptr);
      }
  }
  return key;
}

} // namespace strahler::app
