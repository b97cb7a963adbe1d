#pragma once
// The routes of the Web Mercator tiles that take no query parameter and travel gzipped when the
// client accepts it: vector/{z}/{x}/{y}.mvt and vegetation/{z}/{x}/{y}.json.

#include "tile_request.h"

#include "strahler/base/result.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace strahler::app {

/// Parses /worlds/{world}/vector/{z}/{x}/{y}.mvt (`segments` as parseTarget splits them, six
/// of them) into a Web Mercator request for an mvt tile, gzipped when `acceptEncoding` allows
/// it (then sent as Content-Encoding: gzip). kInvalidInput (→ 400) for coordinates that are
/// not canonical decimals, a name that is not {y}.mvt, and any query parameter. The grid
/// bounds are not checked here.
base::Result<TileRequest> parseVectorTileRoute(const std::string& world,
                                               const std::vector<std::string>& segments,
                                               const std::map<std::string, std::string>& query,
                                               std::string_view acceptEncoding);

/// Parses /worlds/{world}/vegetation/{z}/{x}/{y}.json (`segments` as parseTarget splits them,
/// six of them) into a Web Mercator request for the vegetation instances of a tile, gzipped
/// when `acceptEncoding` allows it (then sent as Content-Encoding: gzip). kInvalidInput
/// (→ 400) for coordinates that are not canonical decimals, a name that is not {y}.json, and
/// any query parameter. The grid bounds and the zoom are checked by the service.
base::Result<TileRequest> parseVegetationRoute(const std::string& world,
                                               const std::vector<std::string>& segments,
                                               const std::map<std::string, std::string>& query,
                                               std::string_view acceptEncoding);

} // namespace strahler::app
