#pragma once

#include "tile_format.h"

#include "strahler/base/result.h"

#include <map>
#include <string>
#include <vector>

namespace strahler::app {

/// A tile request in its one canonical form: every spelling of the same tile (a default size
/// written out, `tif` for `tiff`, `.png?encoding=terrarium` for `.terrarium`) gives the same
/// `key`, so one tile has one cache entry and one ETag.
struct TileRoute {
  TileRequest request; ///< size 0 whenever the default size was asked for.
  std::string key;     ///< "world|scheme|z|x|y|format|size", from the parsed values only.
};

/// Parses the tile route /worlds/{world}/{tiles|local}/{z}/{x}/{y}.{format} (`segments` as
/// parseTarget splits them, six of them) and its query. kInvalidInput (→ 400, the message names
/// the culprit) for: coordinates that are not canonical decimals (a leading zero, a sign),
/// an unknown format, a bad `size` or `encoding`, and any other query parameter.
/// The grid bounds are not checked here.
base::Result<TileRoute> parseTileRoute(const std::string& world,
                                       const std::vector<std::string>& segments,
                                       const std::map<std::string, std::string>& query);

/// The name of `format` in URLs (png, terrarium, png16, tif, exr, drc, glb).
const char* canonicalFormatName(TileFormat format) noexcept;

} // namespace strahler::app
