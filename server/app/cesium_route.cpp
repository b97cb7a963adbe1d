#include "cesium_route.h"

#include "content_encoding.h"
#include "route_parser.h"

#include "strahler/geometry/tile_id.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace strahler::app {
namespace {

base::Error badTerrain(const std::string& why) {
  return base::makeError(base::ErrorCode::kInvalidInput, why);
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

/// The largest TMS zoom whose rows can be flipped without overflow.
constexpr int kDeepestFlippable = 40;

} // namespace

base::Result<unsigned> parseCesiumExtensions(std::string_view list) {
  unsigned bits = 0;
  for (bool more = !list.empty(); more;) {
    const std::size_t dash = list.find('-');
    const std::string_view name = list.substr(0, dash);
    more = dash != std::string_view::npos;
    list = more ? list.substr(dash + 1) : std::string_view{};
    unsigned bit = 0;
    if (name == "octvertexnormals")
      bit = kOctVertexNormals;
    else if (name == "watermask")
      bit = kWaterMask;
    else if (name == "metadata")
      bit = kMetadata;
    else
      return badTerrain("unknown quantized-mesh extension '" + std::string(name.substr(0, 64)) +
                        "' (octvertexnormals, watermask and metadata are served)");
    if (bits & bit)
      return badTerrain("quantized-mesh extension '" + std::string(name) + "' named twice");
    bits |= bit;
  }
  return bits;
}

base::Result<unsigned> cesiumExtensionsFromAccept(std::string_view accept) {
  while (!accept.empty()) {
    const std::size_t comma = accept.find(',');
    std::string_view range = accept.substr(0, comma);
    accept = comma == std::string_view::npos ? std::string_view{} : accept.substr(comma + 1);
    const std::size_t semicolon = range.find(';');
    if (lower(trimmedField(range.substr(0, semicolon))) != "application/vnd.quantized-mesh")
      continue;
    range = semicolon == std::string_view::npos ? std::string_view{} : range.substr(semicolon + 1);
    while (!range.empty()) {
      const std::size_t next = range.find(';');
      const std::string_view parameter = trimmedField(range.substr(0, next));
      range = next == std::string_view::npos ? std::string_view{} : range.substr(next + 1);
      const std::size_t equals = parameter.find('=');
      if (equals != std::string_view::npos &&
          lower(trimmedField(parameter.substr(0, equals))) == "extensions") {
        std::string_view value = trimmedField(parameter.substr(equals + 1));
        if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
          value = value.substr(1, value.size() - 2);
        return parseCesiumExtensions(value);
      }
    }
    return 0u;
  }
  return 0u;
}

base::Result<TileRequest> parseCesiumTerrainRoute(const std::string& world,
                                                  const std::vector<std::string>& s,
                                                  const std::map<std::string, std::string>& query,
                                                  std::string_view accept,
                                                  std::string_view acceptEncoding) {
  for (const auto& [name, value] : query)
    if (name != "extensions" && name != "v")
      return badTerrain("unknown query parameter '" + name.substr(0, 64) +
                        "' (terrain tiles take only extensions and v)");
  STRAHLER_ASSIGN_OR_RETURN(const geometry::TileId tms,
                            parseZxy(std::span(s).subspan(3), ".terrain", "a Cesium terrain tile"));
  TileRequest request;
  request.world = world;
  request.scheme = tiling::SchemeKind::kGeographic;
  request.format = TileFormat::kQuantizedMesh;
  // TMS rows count from the south; a row outside the level stays outside after the flip, but
  // is refused here, so that the message names the row the client asked for (404). A level
  // deeper than kDeepestFlippable, refused later as outside the grid, flips as that one does.
  const int level = std::min(tms.z, kDeepestFlippable);
  const std::int64_t rows = std::int64_t{1} << level;
  if (tms.y >= rows)
    return base::makeError(base::ErrorCode::kNotFound,
                           "tile " + std::to_string(tms.z) + "/" + std::to_string(tms.x) + "/" +
                               std::to_string(tms.y) + " is outside the grid: level " +
                               std::to_string(tms.z) + " has TMS rows 0.." +
                               std::to_string(rows - 1));
  request.tile = {tms.z, tms.x, geometry::flipRow(level, tms.y)};
  if (const auto e = query.find("extensions"); e != query.end()) {
    STRAHLER_ASSIGN_OR_RETURN(request.options.extensions, parseCesiumExtensions(e->second));
  } else {
    STRAHLER_ASSIGN_OR_RETURN(request.options.extensions, cesiumExtensionsFromAccept(accept));
  }
  request.options.gzip = acceptsGzip(acceptEncoding);
  return request;
}

} // namespace strahler::app
