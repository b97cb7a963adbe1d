#pragma once

#include <string>
#include <vector>

namespace strahler::app {

/// The resources of the server's contract (DESIGN.md), as the router tells them apart.
enum class Endpoint {
  kIndex,          ///< /: the viewer, or a list of the worlds.
  kGame,           ///< /game: the viewer's game.html.
  kCesium,         ///< /cesium: the viewer's cesium.html (CesiumJS on the Cesium terrain).
  kHealth,         ///< /health.
  kMetrics,        ///< /metrics (Prometheus).
  kWorldList,      ///< /worlds.
  kWorld,          ///< /worlds/{id}: its metadata.
  kTileJson,       ///< /worlds/{id}/tilejson.json.
  kRivers,         ///< /worlds/{id}/rivers.geojson.
  kFeatures,       ///< /worlds/{id}/features.geojson: the artist's vector map as drawn.
  kTile,           ///< /worlds/{id}/{tiles|local}/{z}/{x}/{y}.{format} (parseTileRoute).
  kCesiumLayer,    ///< /worlds/{id}/cesium/layer.json.
  kCesiumTerrain,  ///< /worlds/{id}/cesium/{z}/{x}/{y}.terrain (parseCesiumTerrainRoute).
  kLayerTile,      ///< /worlds/{id}/layers/{name}/[local/]{z}/{x}/{y}.png (parseLayerRoute).
  kLayerTileJson,  ///< /worlds/{id}/layers/{name}/tilejson.json: one layer's TileJSON.
  kNoSuchResource, ///< Anything else under /worlds/{id}: 404 once the world is known.
  kStaticFile,     ///< Anything else: a file of the built viewer, or 404.
  kVectorTileJson, ///< /worlds/{id}/vector/tilejson.json.
  kVectorTile,     ///< /worlds/{id}/vector/{z}/{x}/{y}.mvt (parseVectorTileRoute).
  kVegetationTile, ///< /worlds/{id}/vegetation/{z}/{x}/{y}.json (parseVegetationRoute).
};

/// What a request target names: its endpoint and, under /worlds/{id}, the world.
struct Route {
  Endpoint endpoint = Endpoint::kStaticFile;
  std::string world; ///< The {id} of /worlds/{id}/...; "" for the other endpoints.
};

/// The endpoint `segments` (parseTarget's, decoded) name, by their shape only: the world is not
/// looked up and the tile route is not parsed yet.
Route routeOf(const std::vector<std::string>& segments);

} // namespace strahler::app
