#pragma once

#include "world_bounds.h"

#include "strahler/construction/world_data.h"
#include "strahler/geometry/vec2.h"
#include "strahler/tiling/tile_scheme.h"

#include <cstddef>
#include <string>
#include <vector>

namespace strahler::app {

/// `url` with the world's content version appended as its `v` query parameter ("?v=" or "&v=").
std::string withVersion(const std::string& url, const std::string& version);

/// The metadata document of a served world (GET /worlds/{id}), as JSON text: its name, bounds,
/// centre, size, generator, cache key and content `version` (worldVersion(): the pages add it
/// to the tile URLs they build), and the zooms of both pyramids (`local` is its local pyramid).
std::string worldMetadataJson(const std::string& id, const construction::WorldData& data,
                              const tiling::TileScheme& local, const std::string& version);

/// The document of GET /worlds: a JSON array of the worlds' metadata documents, in order.
std::string worldListJson(const std::vector<const std::string*>& metadata);

/// The TileJSON 3.0.0 document of world `id` (a MapLibre raster-dem source), whose tiles lie
/// under the absolute URL `base` (".../worlds/{id}") and carry the world's content `version`.
std::string tileJson(const std::string& id, const std::string& base, const LonLatBox& bounds,
                     geometry::Vec2 center, const std::string& version);

/// The TileJSON 3.0.0 document of one layer of world `id` (a MapLibre raster source):
/// `name` its name, `query` what its tile URLs append (layerQuery()), `description` its
/// encoding; tiles under `base` + "/layers/{name}/{z}/{x}/{y}.png", with the world's content
/// `version`.
std::string layerTileJson(const std::string& id, const std::string& base, const std::string& name,
                          const std::string& query, const std::string& description,
                          const LonLatBox& bounds, geometry::Vec2 center,
                          const std::string& version);

/// The document of GET /worlds/{id}/features.geojson: a GeoJSON FeatureCollection of what was
/// drawn (lon/lat as drawn; "kind" and the optional elevation, radius and name), in the order
/// mountains, ridges, rivers; empty when the world has no features. Invalid UTF-8 in a name
/// becomes U+FFFD.
std::string featuresGeoJson(const input::Features& features);

/// The document of GET /health.
std::string healthJson(std::size_t worlds);

} // namespace strahler::app
