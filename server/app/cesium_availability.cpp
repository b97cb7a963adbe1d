#include "cesium_availability.h"

#include "strahler/geometry/tile_id.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace strahler::app {
namespace {

using nlohmann::json;

/// The column or TMS row of level z that holds degree `v` measured from −180 (or −90).
std::int64_t cell(double fromOrigin, int z, std::int64_t count) {
  const double side = 180.0 / static_cast<double>(std::int64_t{1} << z);
  return std::clamp(static_cast<std::int64_t>(std::floor(fromOrigin / side)), std::int64_t{0},
                    count - 1);
}

json rangeJson(const CesiumAvailability::Range& r) {
  return {{"startX", r.startX}, {"startY", r.startY}, {"endX", r.endX}, {"endY", r.endY}};
}

} // namespace

CesiumAvailability::CesiumAvailability(const LonLatBox& land, int maxZoom)
    : land_(land), maxZoom_(maxZoom) {}

std::optional<CesiumAvailability::Range> CesiumAvailability::level(int z) const {
  if (z < 0 || z > maxZoom_)
    return std::nullopt;
  const std::int64_t rows = std::int64_t{1} << z;
  if (z == 0)
    return Range{0, 0, 1, 0};
  return Range{cell(land_.west + 180.0, z, 2 * rows), cell(land_.south + 90.0, z, rows),
               cell(land_.east + 180.0, z, 2 * rows), cell(land_.north + 90.0, z, rows)};
}

bool CesiumAvailability::available(const geometry::TileId& tile) const {
  const std::optional<Range> r = level(tile.z);
  if (!r)
    return false;
  const std::int64_t tmsRow = geometry::flipRow(tile.z, tile.y);
  return tile.x >= r->startX && tile.x <= r->endX && tmsRow >= r->startY && tmsRow <= r->endY;
}

std::string CesiumAvailability::metadataJson(const geometry::TileId& tile) const {
  if (tile.z % kMetadataLevels != 0)
    return {};
  const std::int64_t tmsRow = geometry::flipRow(tile.z, tile.y);
  json levels = json::array();
  for (int k = 1; k <= kMetadataLevels && tile.z + k <= maxZoom_; ++k) {
    json ranges = json::array();
    const std::optional<Range> r = level(tile.z + k);
    // The descendants of the tile at level z + k, clipped to the level's available range.
    const std::int64_t scale = std::int64_t{1} << k;
    const Range under{tile.x * scale, tmsRow * scale, (tile.x + 1) * scale - 1,
                      (tmsRow + 1) * scale - 1};
    const Range clipped{std::max(r->startX, under.startX), std::max(r->startY, under.startY),
                        std::min(r->endX, under.endX), std::min(r->endY, under.endY)};
    if (clipped.startX <= clipped.endX && clipped.startY <= clipped.endY)
      ranges.push_back(rangeJson(clipped));
    levels.push_back(std::move(ranges));
  }
  return json{{"available", std::move(levels)}}.dump();
}

std::string CesiumAvailability::layerJson(const std::string& name,
                                          const std::string& version) const {
  json available = json::array();
  for (int z = 0; z <= std::min(kMetadataLevels, maxZoom_); ++z)
    available.push_back(json::array({rangeJson(*level(z))}));
  const json layer = {
      {"tilejson", "2.1.0"},
      {"name", name},
      {"description", "strahler terrain (quantized-mesh-1.0; sea level is the WGS84 ellipsoid)"},
      {"version", version},
      {"format", "quantized-mesh-1.0"},
      {"attribution", "strahler (procedural terrain)"},
      {"scheme", "tms"},
      {"projection", "EPSG:4326"},
      {"tiles", {"{z}/{x}/{y}.terrain?v={version}"}},
      {"extensions", {"octvertexnormals", "watermask", "metadata"}},
      {"minzoom", 0},
      {"maxzoom", maxZoom_},
      {"bounds", {land_.west, land_.south, land_.east, land_.north}},
      {"available", std::move(available)},
      {"metadataAvailability", kMetadataLevels}};
  return layer.dump();
}

} // namespace strahler::app
