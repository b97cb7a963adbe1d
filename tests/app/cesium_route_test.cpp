#include "cesium_availability.h"
#include "cesium_route.h"
#include "result_matchers.h"
#include "route_parser.h"
#include "router.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace strahler::app {
namespace {

using test_support::valueOf;

/// The request of a /worlds/w/cesium/... target with these headers.
base::Result<TileRequest> parse(const std::string& target, std::string_view accept = "",
                                std::string_view acceptEncoding = "") {
  auto t = parseTarget(target);
  if (!t)
    return t.error();
  return parseCesiumTerrainRoute("w", t.value().segments, t.value().query, accept, acceptEncoding);
}

TEST(CesiumRoute, TheRouterNamesLayerJsonAndTerrainTiles) {
  EXPECT_EQ(routeOf({"worlds", "w", "cesium", "layer.json"}).endpoint, Endpoint::kCesiumLayer);
  EXPECT_EQ(routeOf({"worlds", "w", "cesium", "1", "2", "3.terrain"}).endpoint,
            Endpoint::kCesiumTerrain);
  EXPECT_EQ(routeOf({"worlds", "w", "cesium", "other.json"}).endpoint, Endpoint::kNoSuchResource);
}

TEST(CesiumRoute, TmsRowsBecomeRowsFromTheNorth) {
  const TileRequest r = valueOf(parse("/worlds/w/cesium/3/9/2.terrain"));
  EXPECT_EQ(r.scheme, tiling::SchemeKind::kGeographic);
  EXPECT_EQ(r.format, TileFormat::kQuantizedMesh);
  EXPECT_EQ(r.kind(), TileKind::kTerrain);
  EXPECT_EQ(r.tile, (geometry::TileId{3, 9, 5})); // 2^3 − 1 − 2
  EXPECT_EQ(r.world, "w");
  EXPECT_EQ(r.options.extensions, 0u);
  EXPECT_FALSE(r.options.gzip);
  // A row past the level is refused as not found (404), naming the TMS row asked for.
  const auto past = parse("/worlds/w/cesium/3/9/8.terrain");
  ASSERT_FALSE(past.ok());
  EXPECT_EQ(past.error().code, base::ErrorCode::kNotFound);
  EXPECT_EQ(past.error().message, "tile 3/9/8 is outside the grid: level 3 has TMS rows 0..7");
  EXPECT_LT(valueOf(parse("/worlds/w/cesium/60/0/0.terrain")).tile.y, std::int64_t{1} << 41);
}

TEST(CesiumRoute, ExtensionsComeFromCesiumJsAcceptHeaderInAnyOrder) {
  const char* accept = "application/vnd.quantized-mesh;extensions=watermask-octvertexnormals-"
                       "metadata,application/octet-stream;q=0.9,*/*;q=0.01";
  EXPECT_EQ(valueOf(parse("/worlds/w/cesium/0/0/0.terrain", accept)).options.extensions,
            kOctVertexNormals | kWaterMask | kMetadata);
  EXPECT_EQ(valueOf(parse("/worlds/w/cesium/0/0/0.terrain",
                          "application/vnd.quantized-mesh;extensions=octvertexnormals,"
                          "application/octet-stream;q=0.9"))
                .options.extensions,
            kOctVertexNormals);
  EXPECT_EQ(valueOf(parse("/worlds/w/cesium/0/0/0.terrain",
                          "application/vnd.quantized-mesh,application/octet-stream;q=0.9"))
                .options.extensions,
            0u);
  EXPECT_EQ(valueOf(parse("/worlds/w/cesium/0/0/0.terrain", "*/*")).options.extensions, 0u);
}

TEST(CesiumRoute, TheExtensionsQueryOfCesiumNativeWinsOverTheHeader) {
  const auto r =
      valueOf(parse("/worlds/w/cesium/0/0/0.terrain?extensions=metadata-watermask&v=1.0.0",
                    "application/vnd.quantized-mesh;extensions=octvertexnormals"));
  EXPECT_EQ(r.options.extensions, kWaterMask | kMetadata);
}

TEST(CesiumRoute, GzipOnlyWhenAccepted) {
  EXPECT_TRUE(valueOf(parse("/worlds/w/cesium/0/0/0.terrain", "", "gzip, deflate")).options.gzip);
  EXPECT_FALSE(valueOf(parse("/worlds/w/cesium/0/0/0.terrain", "", "gzip;q=0")).options.gzip);
  // Each spelling of the request that gives other bytes has its own cache key.
  const std::string plain = tileKey(valueOf(parse("/worlds/w/cesium/0/0/0.terrain")));
  EXPECT_NE(plain, tileKey(valueOf(parse("/worlds/w/cesium/0/0/0.terrain", "", "gzip"))));
  EXPECT_NE(plain, tileKey(valueOf(parse("/worlds/w/cesium/0/0/0.terrain?extensions=metadata"))));
  EXPECT_EQ(plain, tileKey(valueOf(parse("/worlds/w/cesium/0/0/0.terrain?v=2"))));
  EXPECT_EQ(
      tileKey(valueOf(parse("/worlds/w/cesium/0/0/0.terrain?extensions=metadata-watermask"))),
      tileKey(valueOf(parse("/worlds/w/cesium/0/0/0.terrain?extensions=watermask-metadata"))));
}

TEST(CesiumRoute, BadTerrainRequestsNameTheirFault) {
  const std::pair<const char*, const char*> cases[] = {
      {"/worlds/w/cesium/0/0/0.png", "{y}.terrain"},
      {"/worlds/w/cesium/0/0/.terrain", "{y}.terrain"},
      {"/worlds/w/cesium/01/0/0.terrain", "tile coordinate"},
      {"/worlds/w/cesium/0/-1/0.terrain", "tile coordinate"},
      {"/worlds/w/cesium/0/0/0.terrain?extensions=vertexnormals",
       "unknown quantized-mesh extension"},
      {"/worlds/w/cesium/0/0/0.terrain?extensions=metadata-metadata", "named twice"},
      {"/worlds/w/cesium/0/0/0.terrain?extensions=metadata-", "unknown quantized-mesh extension"},
      {"/worlds/w/cesium/0/0/0.terrain?size=64", "unknown query parameter 'size'"},
  };
  for (const auto& [target, message] : cases) {
    const auto r = parse(target);
    ASSERT_FALSE(r.ok()) << target;
    EXPECT_EQ(r.error().code, base::ErrorCode::kInvalidInput);
    EXPECT_NE(r.error().message.find(message), std::string::npos) << r.error().message;
  }
  const auto header = parse("/worlds/w/cesium/0/0/0.terrain",
                            "application/vnd.quantized-mesh;extensions=octvertexnormals-bogus");
  ASSERT_FALSE(header.ok());
  EXPECT_NE(header.error().message.find("'bogus'"), std::string::npos);
}

TEST(CesiumAvailability, LevelZeroHasBothRootsAndDeeperLevelsTheLandsTiles) {
  const CesiumAvailability a({2.3, 39.2, 3.5, 40.1}, 17); // Mallorca
  EXPECT_TRUE(a.available({0, 0, 0}));
  EXPECT_TRUE(a.available({0, 1, 0}));
  const auto r1 = a.level(1);
  ASSERT_TRUE(r1);
  EXPECT_EQ(r1->startX, 2); // lon 0..90, TMS row 1: lat 0..90
  EXPECT_EQ(r1->endX, 2);
  EXPECT_EQ(r1->startY, 1);
  EXPECT_EQ(r1->endY, 1);
  EXPECT_TRUE(a.available({1, 2, 0})); // row 0 from the north
  EXPECT_FALSE(a.available({1, 1, 0}));
  EXPECT_FALSE(a.level(18).has_value());
  // At level 12, tiles are 180/4096° wide: the land's corners fall in these columns and rows.
  const auto r12 = a.level(12);
  ASSERT_TRUE(r12);
  EXPECT_EQ(r12->startX, static_cast<std::int64_t>((2.3 + 180.0) / (180.0 / 4096)));
  EXPECT_EQ(r12->endX, static_cast<std::int64_t>((3.5 + 180.0) / (180.0 / 4096)));
  EXPECT_EQ(r12->startY, static_cast<std::int64_t>((39.2 + 90.0) / (180.0 / 4096)));
  EXPECT_EQ(r12->endY, static_cast<std::int64_t>((40.1 + 90.0) / (180.0 / 4096)));
}

TEST(CesiumAvailability, MetadataTilesCarryTheNextLevelsOfTheirDescendants) {
  const CesiumAvailability a({2.3, 39.2, 3.5, 40.1}, 17);
  EXPECT_EQ(a.metadataJson({3, 8, 2}), "");
  const auto root = nlohmann::json::parse(a.metadataJson({0, 1, 0}));
  ASSERT_EQ(root["available"].size(), 10u);
  for (int k = 1; k <= 10; ++k) {
    const auto& ranges = root["available"][static_cast<std::size_t>(k - 1)];
    ASSERT_EQ(ranges.size(), 1u) << k;
    EXPECT_EQ(ranges[0]["startX"], a.level(k)->startX);
    EXPECT_EQ(ranges[0]["endY"], a.level(k)->endY);
  }
  // The west root holds none of the land.
  const auto west = nlohmann::json::parse(a.metadataJson({0, 0, 0}));
  for (const auto& ranges : west["available"])
    EXPECT_TRUE(ranges.empty());
  // Level 10's tile over the land lists levels 11..17 only (the pyramid ends there).
  const auto r10 = a.level(10);
  const geometry::TileId t10{10, r10->startX, (1 << 10) - 1 - r10->startY};
  const auto deep = nlohmann::json::parse(a.metadataJson(t10));
  EXPECT_EQ(deep["available"].size(), 7u);
  const auto& first = deep["available"][0][0];
  EXPECT_GE(first["startX"].get<std::int64_t>(), 2 * r10->startX);
  EXPECT_LE(first["endX"].get<std::int64_t>(), 2 * r10->startX + 1);
}

TEST(CesiumAvailability, LayerJsonHasWhatCesiumClientsRead) {
  const auto layer = nlohmann::json::parse(
      CesiumAvailability({2.3, 39.2, 3.5, 40.1}, 17).layerJson("mallorca", "0123456789abcdef"));
  EXPECT_EQ(layer["format"], "quantized-mesh-1.0");
  EXPECT_EQ(layer["scheme"], "tms");
  EXPECT_EQ(layer["projection"], "EPSG:4326");
  EXPECT_EQ(layer["tiles"][0], "{z}/{x}/{y}.terrain?v={version}");
  EXPECT_EQ(layer["version"], "0123456789abcdef"); // the world's content version
  EXPECT_EQ(layer["minzoom"], 0);
  EXPECT_EQ(layer["maxzoom"], 17);
  EXPECT_EQ(layer["metadataAvailability"], 10);
  EXPECT_EQ(layer["extensions"],
            nlohmann::json::array({"octvertexnormals", "watermask", "metadata"}));
  EXPECT_EQ(layer["bounds"].size(), 4u);
  EXPECT_TRUE(layer["attribution"].is_string());
  ASSERT_EQ(layer["available"].size(), 11u);
  EXPECT_EQ(layer["available"][0][0]["endX"], 1);
}

} // namespace
} // namespace strahler::app
