#include "vegetation_route.h"

#include "content_encoding.h"
#include "route_parser.h"

namespace strahler::app {
namespace {

base::Error badVegetationTile(const std::string& why) {
  return base::makeError(base::ErrorCode::kInvalidInput, why);
}

} // namespace

base::Result<TileRequest> parseVegetationRoute(const std::string& world,
                                               const std::vector<std::string>& s,
                                               const std::map<std::string, std::string>& query,
                                               std::string_view acceptEncoding) {
  if (!query.empty())
    return badVegetationTile("unknown query parameter '" + query.begin()->first.substr(0, 64) +
                             "' (vegetation tiles take none)");
  const std::string& last = s[5];
  const std::string suffix = ".json";
  if (last.size() <= suffix.size() ||
      last.compare(last.size() - suffix.size(), suffix.size(), suffix) != 0)
    return badVegetationTile("a vegetation tile is named {y}.json");
  auto z = parseDecimal(s[3], 2), x = parseDecimal(s[4], 10),
       y = parseDecimal(last.substr(0, last.size() - suffix.size()), 10);
  for (auto* v : {&z, &x, &y})
    if (!*v)
      return badVegetationTile("tile coordinate " + v->error().message);
  TileRequest request;
  request.world = world;
  request.scheme = tiling::SchemeKind::kWebMercator;
  request.format = TileFormat::kVegetationJson;
  request.tile = {static_cast<int>(z.value()), x.value(), y.value()};
  request.options.gzip = acceptsGzip(acceptEncoding);
  return request;
}

} // namespace strahler::app
