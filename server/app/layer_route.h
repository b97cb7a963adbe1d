#pragma once

#include "tile_request.h"

#include "strahler/base/result.h"

#include <map>
#include <string>
#include <vector>

namespace strahler::app {

/// The sun of a hillshade layer tile that names none (the relief tiles' sun).
inline constexpr double kDefaultSunAzimuthDeg = 315.0, kDefaultSunAltitudeDeg = 45.0;

/// The layer `name` with the parameters of `query` (`size` aside, which any tile takes), in
/// canonical form: `species` (tree, bush; default tree) on vegetation only, `azimuth`
/// (0 ≤ a < 360, default 315) and `altitude` (0 ≤ a ≤ 90, default 45) on hillshade only,
/// plain decimals (digits, at most six after a point). kNotFound (→ 404) for an unknown layer
/// or species; kInvalidInput (→ 400, naming the culprit) for a malformed or out-of-range
/// value, a parameter the layer does not take, or any other parameter.
base::Result<LayerOptions> parseLayerOptions(const std::string& name,
                                             const std::map<std::string, std::string>& query);

/// Parses /worlds/{world}/layers/{name}/{z}/{x}/{y}.png (Web Mercator, seven segments) or
/// /worlds/{world}/layers/{name}/local/{z}/{x}/{y}.png (the local pyramid, eight) and its
/// query (`size` as tiles take it, and parseLayerOptions()'s) into its canonical request.
/// Errors as parseLayerOptions(), and kInvalidInput for coordinates that are not canonical
/// decimals or a name that is not {y}.png. The grid bounds are not checked here.
base::Result<TileRequest> parseLayerRoute(const std::string& world,
                                          const std::vector<std::string>& segments,
                                          const std::map<std::string, std::string>& query);

/// What a tile of layer `name` holds and how it is encoded (its TileJSON's description).
const char* layerDescription(LayerName name) noexcept;

/// The query string (with its '?', or "") that asks for `layer`'s parameters where they are
/// not the defaults: what a layer's TileJSON appends to its tile URLs.
std::string layerQuery(const LayerOptions& layer);

} // namespace strahler::app
