#include "tile_route.h"

#include "route_parser.h"

#include <charconv>

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
  const bool mesh = isMeshFormat(format);
  const int lo = mesh ? TileSizes::kMeshMin : TileSizes::kRasterMin;
  const int hi = mesh ? TileSizes::kMeshMax : TileSizes::kRasterMax;
  if (size < lo || size > hi)
    return badTile("size must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return size == (mesh ? TileSizes::kMeshDefault : TileSizes::kRasterDefault) ? 0 : size;
}

} // namespace

const char* canonicalFormatName(TileFormat format) noexcept {
  switch (format) {
  case TileFormat::kTerrainRgb:
    return "png";
  case TileFormat::kTerrarium:
    return "terrarium";
  case TileFormat::kPng16:
    return "png16";
  case TileFormat::kTiff:
    return "tif";
  case TileFormat::kExr:
    return "exr";
  case TileFormat::kDraco:
    return "drc";
  case TileFormat::kGlb:
    return "glb";
  }
  return "png";
}

base::Result<TileRoute> parseTileRoute(const std::string& world, const std::vector<std::string>& s,
                                       const std::map<std::string, std::string>& query) {
  for (const auto& [name, value] : query)
    if (name != "size" && name != "encoding")
      return badTile("unknown query parameter '" + name.substr(0, 64) +
                     "' (tiles take only size and encoding)");
  const std::string& last = s[5];
  const std::size_t dot = last.find('.');
  if (dot == std::string::npos)
    return badTile("tile name must be {y}.{format}");
  auto z = parseDecimal(s[3], 2), x = parseDecimal(s[4], 10),
       y = parseDecimal(last.substr(0, dot), 10);
  for (auto* v : {&z, &x, &y})
    if (!*v)
      return badTile("tile coordinate " + v->error().message);
  std::string formatName = last.substr(dot + 1);
  if (const auto e = query.find("encoding"); e != query.end()) {
    if (formatName != "png" || (e->second != "terrarium" && e->second != "mapbox"))
      return badTile("encoding must be 'mapbox' or 'terrarium', for png tiles");
    if (e->second == "terrarium")
      formatName = "terrarium";
  }
  STRAHLER_ASSIGN_OR_RETURN(const TileFormat format, parseTileFormat(formatName));
  STRAHLER_ASSIGN_OR_RETURN(const int size, tileSize(query, format));
  const tiling::SchemeKind scheme =
      s[2] == "local" ? tiling::SchemeKind::kLocal : tiling::SchemeKind::kWebMercator;
  TileRoute route{{scheme, {static_cast<int>(z.value()), x.value(), y.value()}, format, size}, {}};
  char number[24];
  auto append = [&](std::int64_t v) {
    route.key.append(number, std::to_chars(number, number + sizeof number, v).ptr);
    route.key.push_back('|');
  };
  route.key.reserve(world.size() + 48);
  route.key.append(world).append(s[2] == "local" ? "|local|" : "|tiles|");
  append(z.value());
  append(x.value());
  append(y.value());
  route.key.append(canonicalFormatName(format)).push_back('|');
  route.key.append(number, std::to_chars(number, number + sizeof number, size).ptr);
  return route;
}

} // namespace strahler::app
