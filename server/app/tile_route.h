#pragma once

#include "tile_request.h"

#include "strahler/base/result.h"

#include <map>
#include <string>
#include <vector>

namespace strahler::app {

/// Parses the tile route /worlds/{world}/{tiles|local}/{z}/{x}/{y}.{format} (`segments` as
/// parseTarget splits them, six of them) and its query into the request in its one canonical
/// form: every spelling of the same tile (a default size written out, `tif` for `tiff`,
/// `.png?encoding=terrarium` for `.terrarium`) gives the same request, hence the same
/// tileKey(): one cache entry and one ETag. kInvalidInput (→ 400, the message names the
/// culprit) for: coordinates that are not canonical decimals (a leading zero, a sign), an
/// unknown format, a bad `size` or `encoding`, and any other query parameter. The grid bounds
/// are not checked here.
base::Result<TileRequest> parseTileRoute(const std::string& world,
                                         const std::vector<std::string>& segments,
                                         const std::map<std::string, std::string>& query);

} // namespace strahler::app
