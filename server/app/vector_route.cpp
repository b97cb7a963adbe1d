#include "vector_route.h"

#include "content_encoding.h"
#include "route_parser.h"

namespace strahler::app {
namespace {

base::Error badVectorTile(const std::string& why) {
  return base::makeError(base::ErrorCode::kInvalidInput, why);
}

} // namespace

base::Result<TileRequest> parseVectorTileRoute(const std::string& world,
                                               const std::vector<std::string>& s,
                                               const std::map<std::string, std::string>& query,
                                               std::string_view acceptEncoding) {
  if (!query.empty())
    return badVectorTile("unknown query parameter '" + query.begin()->first.substr(0, 64) +
                         "' (vector tiles take none)");
  const std::string& last = s[5];
  const std::string suffix = ".mvt";
  if (last.size() <= suffix.size() ||
      last.compare(last.size() - suffix.size(), suffix.size(), suffix) != 0)
    return badVectorTile("a vector tile is named {y}.mvt");
  auto z = parseDecimal(s[3], 2), x = parseDecimal(s[4], 10),
       y = parseDecimal(last.substr(0, last.size() - suffix.size()), 10);
  for (auto* v : {&z, &x, &y})
    if (!*v)
      return badVectorTile("tile coordinate " + v->error().message);
  TileRequest request;
  request.world = world;
  request.scheme = tiling::SchemeKind::kWebMercator;
  request.format = TileFormat::kMvt;
  request.tile = {static_cast<int>(z.value()), x.value(), y.value()};
  request.options.gzip = acceptsGzip(acceptEncoding);
  return request;
}

} // namespace strahler::app
