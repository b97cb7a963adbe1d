#include "world_documents.h"

#include <nlohmann/json.hpp>

namespace strahler::app {
namespace {

using nlohmann::json;

constexpr int kTileJsonMaxZoom = 16; // DEM detail advertised; deeper tiles are still served

} // namespace

std::string withVersion(const std::string& url, const std::string& version) {
  return url + (url.find('?') == std::string::npos ? "?v=" : "&v=") + version;
}

std::string worldMetadataJson(const std::string& id, const construction::WorldData& data,
                              const tiling::TileScheme& local, const std::string& version) {
  const LonLatBox b = worldBounds(data);
  const geometry::Aabb root = local.localBounds({0, 0, 0});
  const json metadata = {{"id", id},
                         {"name", data.name},
                         {"bounds", {b.west, b.south, b.east, b.north}},
                         {"center", {data.projectionCenter.x, data.projectionCenter.y}},
                         {"areaKm2", data.areaKm2()},
                         {"nodes", data.network.nodes.size()},
                         {"mouths", data.network.mouths.size()},
                         {"terrainPrimitives", data.terrain.size()},
                         {"riverPrimitives", data.rivers.size()},
                         {"seed", data.params.seed},
                         {"generatorVersion", data.generatorVersion},
                         {"cacheKey", data.cacheKey},
                         {"version", version},
                         {"web", {{"minzoom", 0}, {"maxzoom", tiling::TileScheme::kMaxWebZoom}}},
                         {"local",
                          {{"minzoom", 0},
                           {"maxzoom", local.maxZoom()},
                           {"rootSouthWest", {root.min.x, root.min.y}},
                           {"rootSide", root.size().x}}}};
  return metadata.dump();
}

std::string worldListJson(const std::vector<const std::string*>& metadata) {
  // What json::array of the parsed documents would dump: no spaces between the elements.
  std::string list = "[";
  for (const std::string* document : metadata) {
    if (list.size() > 1)
      list += ',';
    list += *document;
  }
  return list + "]";
}

std::string tileJson(const std::string& id, const std::string& base, const LonLatBox& bounds,
                     geometry::Vec2 center, const std::string& version) {
  const json tj = {{"tilejson", "3.0.0"},
                   {"name", id},
                   {"description", "strahler terrain (Terrain-RGB heightmap)"},
                   {"version", "1.0.0"},
                   {"scheme", "xyz"},
                   {"tiles", {withVersion(base + "/tiles/{z}/{x}/{y}.png", version)}},
                   {"minzoom", 0},
                   {"maxzoom", kTileJsonMaxZoom},
                   {"bounds", {bounds.west, bounds.south, bounds.east, bounds.north}},
                   {"center", {center.x, center.y, 9}},
                   {"tileSize", 256},
                   {"encoding", "mapbox"},
                   {"attribution", "strahler"}};
  return tj.dump();
}

std::string layerTileJson(const std::string& id, const std::string& base, const std::string& name,
                          const std::string& query, const std::string& description,
                          const LonLatBox& bounds, geometry::Vec2 center,
                          const std::string& version) {
  const json tj = {
      {"tilejson", "3.0.0"},
      {"name", id + " " + name},
      {"description", description},
      {"version", "1.0.0"},
      {"scheme", "xyz"},
      {"tiles", {withVersion(base + "/layers/" + name + "/{z}/{x}/{y}.png" + query, version)}},
      {"minzoom", 0},
      {"maxzoom", tiling::TileScheme::kMaxWebZoom},
      {"bounds", {bounds.west, bounds.south, bounds.east, bounds.north}},
      {"center", {center.x, center.y, 9}},
      {"tileSize", 256},
      {"attribution", "strahler"}};
  return tj.dump();
}

std::string featuresGeoJson(const input::Features& features) {
  json list = json::array();
  const auto positions = [](const std::vector<geometry::Vec2>& points) {
    json out = json::array();
    for (const geometry::Vec2 p : points)
      out.push_back({p.x, p.y});
    return out;
  };
  const auto feature = [&](json properties, json geometry) {
    list.push_back({{"type", "Feature"},
                    {"properties", std::move(properties)},
                    {"geometry", std::move(geometry)}});
  };
  for (const input::MountainFeature& m : features.mountains) {
    json properties = {{"kind", "mountain"}};
    if (m.elevation)
      properties["elevation"] = *m.elevation;
    if (m.radius)
      properties["radius"] = *m.radius;
    feature(std::move(properties), {{"type", "Point"}, {"coordinates", {m.lonLat.x, m.lonLat.y}}});
  }
  for (const input::RidgeFeature& r : features.ridges) {
    json properties = {{"kind", "ridge"}};
    if (r.elevation)
      properties["elevation"] = *r.elevation;
    feature(std::move(properties), {{"type", "LineString"}, {"coordinates", positions(r.lonLat)}});
  }
  for (const input::RiverFeature& r : features.rivers) {
    json properties = {{"kind", "river"}};
    if (!r.name.empty())
      properties["name"] = r.name;
    feature(std::move(properties), {{"type", "LineString"}, {"coordinates", positions(r.lonLat)}});
  }
  return json{{"type", "FeatureCollection"}, {"features", std::move(list)}}.dump(
      -1, ' ', false, json::error_handler_t::replace);
}

std::string healthJson(std::size_t worlds) {
  return json{{"status", "ok"}, {"worlds", worlds}}.dump();
}

} // namespace strahler::app
