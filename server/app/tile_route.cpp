#include "tile_route.h"

#include "route_parser.h"

namespace strahler::app {
namespace {

base::Error badTile(const std::string& why) {
  return base::makeError(base::ErrorCode::kInvalidInput, why);
}

/// The size a request asks for, 0 for the format's default (written out or not).
base::Result<int> tileSize(const std::map<std::string, std::string>& query, TileFormat format) {
  const auto q = query.find("size");
  if (q == query.end())
    return 0;
  auto v = parseDecimal(q->second, 4);
  if (!v)
    return badTile("size " + v.error().message);
  const int size = static_cast<int>(v.value());
  const TileSizeRange range = tileSizeRange(tileKind(format));
  if (size < range.min || size > range.max)
    return badTile("size must be in [" + std::to_string(range.min) + ", " +
                   std::to_string(range.max) + "]");
  return size == range.defaultSize ? 0 : size;
}

} // namespace

base::Result<TileRequest> parseTileRoute(const std::string& world,
                                         const std::vector<std::string>& s,
                                         const std::map<std::string, std::string>& query) {
  for (const auto& [name, value] : query)
    if (name != "size" && name != "encoding")
      return badTile("unknown query parameter '" + name.substr(0, 64) +
                     "' (tiles take only size and encoding)");
  const std::string& last = s[5];
  const std::size_t dot = last.find('.');
  if (dot == std::string::npos)
    return badTile("tile name must be {y}.{format}");
  STRAHLER_ASSIGN_OR_RETURN(const geometry::TileId tile,
                            parseTileCoordinates(s[3], s[4], last.substr(0, dot)));
  std::string formatName = last.substr(dot + 1);
  if (const auto e = query.find("encoding"); e != query.end()) {
    if (formatName != "png" || (e->second != "terrarium" && e->second != "mapbox"))
      return badTile("encoding must be 'mapbox' or 'terrarium', for png tiles");
    if (e->second == "terrarium")
      formatName = "terrarium";
  }
  TileRequest request;
  auto format = parseTileFormat(formatName);
  if (!format) // name only what this path serves: the other formats have paths of their own
    return badTile("unknown tile format '" + formatName.substr(0, 64) + "' (under /" + s[2] +
                   "/: png, terrarium, png16, tif, exr, drc, glb or relief)");
  request.format = format.value();
  if (request.kind() == TileKind::kTerrain)
    return badTile("Cesium terrain tiles are served under /worlds/{id}/cesium/ (TMS rows)");
  if (request.kind() == TileKind::kVector)
    return badTile("vector tiles are served under /worlds/{id}/vector/");
  if (request.kind() == TileKind::kVegetation)
    return badTile("vegetation tiles are served under /worlds/{id}/vegetation/");
  STRAHLER_ASSIGN_OR_RETURN(request.options.size, tileSize(query, request.format));
  request.world = world;
  request.scheme = s[2] == "local" ? tiling::SchemeKind::kLocal : tiling::SchemeKind::kWebMercator;
  request.tile = tile;
  return request;
}

} // namespace strahler::app
