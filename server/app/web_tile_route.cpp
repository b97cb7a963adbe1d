#include "web_tile_route.h"

#include "content_encoding.h"
#include "route_parser.h"

#include <span>

namespace strahler::app {
namespace {

/// A `format` tile of the Web Mercator pyramid named {z}/{x}/{y}`suffix` after two segments;
/// `kind` names its tiles in the refusals ("vector" → "a vector tile", "vector tiles").
base::Result<TileRequest> parseWebTile(const std::string& world, TileFormat format,
                                       std::string_view kind, std::string_view suffix,
                                       const std::vector<std::string>& s,
                                       const std::map<std::string, std::string>& query,
                                       std::string_view acceptEncoding) {
  if (!query.empty())
    return base::makeError(base::ErrorCode::kInvalidInput,
                           "unknown query parameter '" + query.begin()->first.substr(0, 64) +
                               "' (" + std::string(kind) + " tiles take none)");
  TileRequest request;
  STRAHLER_ASSIGN_OR_RETURN(
      request.tile, parseZxy(std::span(s).subspan(3), suffix, "a " + std::string(kind) + " tile"));
  request.world = world;
  request.scheme = tiling::SchemeKind::kWebMercator;
  request.format = format;
  request.options.gzip = acceptsGzip(acceptEncoding);
  return request;
}

} // namespace

base::Result<TileRequest> parseVectorTileRoute(const std::string& world,
                                               const std::vector<std::string>& segments,
                                               const std::map<std::string, std::string>& query,
                                               std::string_view acceptEncoding) {
  return parseWebTile(world, TileFormat::kMvt, "vector", ".mvt", segments, query, acceptEncoding);
}

base::Result<TileRequest> parseVegetationRoute(const std::string& world,
                                               const std::vector<std::string>& segments,
                                               const std::map<std::string, std::string>& query,
                                               std::string_view acceptEncoding) {
  return parseWebTile(world, TileFormat::kVegetationJson, "vegetation", ".json", segments, query,
                      acceptEncoding);
}

} // namespace strahler::app
