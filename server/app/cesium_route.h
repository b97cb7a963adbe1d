#pragma once

#include "tile_request.h"

#include "strahler/base/result.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace strahler::app {

/// The extensions a quantized-mesh client asks for, as CesiumExtension bits: a list of
/// "octvertexnormals", "watermask" and "metadata" joined by '-' (in any order; each at most
/// once), as CesiumJS puts it in its Accept header and cesium-native in `?extensions=`.
/// kInvalidInput naming any other.
base::Result<unsigned> parseCesiumExtensions(std::string_view list);

/// The extensions of an Accept header: those of its application/vnd.quantized-mesh media
/// range's `extensions` parameter, none without one.
base::Result<unsigned> cesiumExtensionsFromAccept(std::string_view accept);

/// Parses /worlds/{world}/cesium/{z}/{x}/{y}.terrain (`segments` as parseTarget splits them,
/// six of them; y a TMS row, counted from the south) into its request, rows from the north as
/// in every TileRequest. The extensions come from `?extensions=` when present, else from the
/// Accept header; `?v=` (layer.json's version) is accepted and ignored; gzip when
/// `acceptEncoding` accepts it. kInvalidInput (→ 400) for malformed coordinates, another
/// suffix than .terrain, an unknown extension or any other query parameter.
base::Result<TileRequest> parseCesiumTerrainRoute(const std::string& world,
                                                  const std::vector<std::string>& segments,
                                                  const std::map<std::string, std::string>& query,
                                                  std::string_view accept,
                                                  std::string_view acceptEncoding);

} // namespace strahler::app
