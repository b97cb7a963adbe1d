#include "router.h"

namespace strahler::app {

Route routeOf(const std::vector<std::string>& s) {
  if (s.empty())
    return {Endpoint::kIndex, {}};
  if (s.size() == 1 && s[0] == "game")
    return {Endpoint::kGame, {}};
  if (s.size() == 1 && s[0] == "cesium")
    return {Endpoint::kCesium, {}};
  if (s.size() == 1 && s[0] == "health")
    return {Endpoint::kHealth, {}};
  if (s.size() == 1 && s[0] == "metrics")
    return {Endpoint::kMetrics, {}};
  if (s[0] != "worlds")
    return {Endpoint::kStaticFile, {}};
  if (s.size() == 1)
    return {Endpoint::kWorldList, {}};
  Route route{Endpoint::kNoSuchResource, s[1]};
  if (s.size() == 2)
    route.endpoint = Endpoint::kWorld;
  else if (s.size() == 3 && s[2] == "tilejson.json")
    route.endpoint = Endpoint::kTileJson;
  else if (s.size() == 3 && s[2] == "rivers.geojson")
    route.endpoint = Endpoint::kRivers;
  else if (s.size() == 3 && s[2] == "features.geojson")
    route.endpoint = Endpoint::kFeatures;
  else if (s.size() == 6 && (s[2] == "tiles" || s[2] == "local"))
    route.endpoint = Endpoint::kTile;
  else if (s.size() == 4 && s[2] == "cesium" && s[3] == "layer.json")
    route.endpoint = Endpoint::kCesiumLayer;
  else if (s.size() == 6 && s[2] == "cesium")
    route.endpoint = Endpoint::kCesiumTerrain;
  else if (s.size() == 4 && s[2] == "vector" && s[3] == "tilejson.json")
    route.endpoint = Endpoint::kVectorTileJson;
  else if (s.size() == 6 && s[2] == "vector")
    route.endpoint = Endpoint::kVectorTile;
  else if (s.size() == 6 && s[2] == "vegetation")
    route.endpoint = Endpoint::kVegetationTile;
  else if (s.size() == 5 && s[2] == "layers" && s[4] == "tilejson.json")
    route.endpoint = Endpoint::kLayerTileJson;
  else if ((s.size() == 7 || s.size() == 8) && s[2] == "layers")
    route.endpoint = Endpoint::kLayerTile;
  return route;
}

} // namespace strahler::app
