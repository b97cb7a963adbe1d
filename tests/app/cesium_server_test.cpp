// Cesium terrain over real sockets on 127.0.0.1: layer.json and quantized-mesh tiles as
// CesiumJS and cesium-native ask for them, decoded by the tests' own reader of the format.
#include "gzip.h"
#include "quantized_mesh_reader.h"
#include "result_matchers.h"
#include "tile_server_harness.h"

#include "strahler/construction/world.h"
#include "strahler/geometry/projection.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace strahler::app {
namespace {

using encoding::test_support::DecodedTile;
using encoding::test_support::decodeQuantizedMesh;
using test_support::HttpResponse;
using test_support::request;
using test_support::Running;

constexpr const char* kCesiumJsAccept =
    "Accept: application/vnd.quantized-mesh;extensions=octvertexnormals-watermask-metadata,"
    "application/octet-stream;q=0.9,*/*;q=0.01\r\n";

/// The default island, as the server evaluates it.
const construction::World& island() {
  static const construction::World world(strahler::test_support::valueOf(
      construction::generateWorldData(strahler::test_support::defaultIslandSpec(), "k")));
  return world;
}

/// A tile of level z (TMS row) holding the island's centre.
struct Tms {
  int z = 0;
  std::int64_t x = 0, y = 0;
  std::string path() const {
    return "/worlds/island/cesium/" + std::to_string(z) + "/" + std::to_string(x) + "/" +
           std::to_string(y) + ".terrain";
  }
  double side() const { return 180.0 / static_cast<double>(std::int64_t{1} << z); }
  double west() const { return -180.0 + static_cast<double>(x) * side(); }
  double south() const { return -90.0 + static_cast<double>(y) * side(); }
};

Tms tileOfCentre(int z) {
  const geometry::Vec2 c = island().data().projectionCenter;
  const double side = 180.0 / static_cast<double>(std::int64_t{1} << z);
  return {z, static_cast<std::int64_t>(std::floor((c.x + 180.0) / side)),
          static_cast<std::int64_t>(std::floor((c.y + 90.0) / side))};
}

DecodedTile fetchTile(const Running& s, const Tms& t,
                      const std::string& headers = kCesiumJsAccept) {
  const HttpResponse r = request(s.port(), t.path(), "GET", headers);
  EXPECT_EQ(r.status, 200) << t.path() << " " << r.body;
  EXPECT_EQ(r.headers.at("content-type"), "application/vnd.quantized-mesh");
  return decodeQuantizedMesh(r.body);
}

TEST(CesiumTerrainServer, LayerJsonDescribesTheTerrain) {
  Running s;
  const HttpResponse r = request(s.port(), "/worlds/island/cesium/layer.json");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.headers.at("content-type"), "application/json");
  const auto layer = nlohmann::json::parse(r.body);
  EXPECT_EQ(layer["format"], "quantized-mesh-1.0");
  EXPECT_EQ(layer["scheme"], "tms");
  EXPECT_EQ(layer["metadataAvailability"], 10);
  const auto bounds = nlohmann::json::parse(request(s.port(), "/worlds/island").body)["bounds"];
  EXPECT_EQ(layer["bounds"], bounds);
}

TEST(CesiumTerrainServer, ATileCarriesTheExtensionsCesiumJsAsksForAndTheWorldsHeights) {
  Running s;
  const Tms t = tileOfCentre(12);
  const HttpResponse r = request(s.port(), t.path() + "?v=1.0.0", "GET", kCesiumJsAccept);
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.headers.at("vary"), "Accept, Accept-Encoding");
  EXPECT_EQ(r.headers.count("content-encoding"), 0u);
  EXPECT_NE(r.headers.at("server-timing").find("eval;dur="), std::string::npos);
  const DecodedTile tile = decodeQuantizedMesh(r.body);
  // Level 12 carries no availability (levels 0, 10, 20 … do).
  EXPECT_EQ(tile.extensionOrder, (std::vector<int>{1, 2}));
  EXPECT_EQ(tile.extensions.at(1).size(), 2 * tile.vertexCount());
  EXPECT_GT(tile.vertexCount(), 16u);
  EXPECT_LT(tile.vertexCount(), 65u * 65u);
  EXPECT_GT(tile.maximumHeight, 50.0f);
  // Every vertex is a sample of the world, at its height (within the height quantum and the
  // ~0.1 m that rounding u/v to 1/32767 of the tile moves it), the sea at 0.
  const geometry::LocalProjection projection(island().data().projectionCenter.x,
                                             island().data().projectionCenter.y);
  // The grid's evaluation spacing: a quarter of its north-south step.
  const double spacing = 0.25 * t.side() / 64.0 * M_PI / 180.0 * geometry::kEarthRadius;
  const double quantum = (tile.maximumHeight - tile.minimumHeight) / 32767.0;
  double worst = 0.0;
  for (std::size_t k = 0; k < tile.vertexCount(); ++k) {
    // The grid sample the vertex stands for.
    const double i = std::round(tile.u[k] / 32767.0 * 64.0),
                 j = std::round(tile.v[k] / 32767.0 * 64.0);
    EXPECT_NEAR(tile.u[k], i / 64.0 * 32767.0, 0.5);
    EXPECT_NEAR(tile.v[k], j / 64.0 * 32767.0, 0.5);
    const geometry::Vec2 lonLat{t.west() + i / 64.0 * t.side(), t.south() + j / 64.0 * t.side()};
    const double expected = std::max(0.0, island().height(projection.forward(lonLat), spacing));
    worst = std::max(worst, std::abs(tile.heightOf(k) - expected));
  }
  EXPECT_LT(worst, quantum + 1e-3);
}

TEST(CesiumTerrainServer, NeighboursShareTheirEdgeVertices) {
  Running s;
  const Tms a = tileOfCentre(13), b{a.z, a.x + 1, a.y};
  const DecodedTile ta = fetchTile(s, a), tb = fetchTile(s, b);
  std::map<int, double> eastOfA, westOfB;
  for (std::uint32_t k : ta.east)
    eastOfA[ta.v[k]] = ta.heightOf(k);
  for (std::uint32_t k : tb.west)
    westOfB[tb.v[k]] = tb.heightOf(k);
  ASSERT_EQ(eastOfA.size(), westOfB.size());
  const double quanta = (ta.maximumHeight - ta.minimumHeight) / 32767.0 +
                        (tb.maximumHeight - tb.minimumHeight) / 32767.0;
  for (const auto& [v, h] : eastOfA) {
    ASSERT_EQ(westOfB.count(v), 1u) << v;
    EXPECT_NEAR(h, westOfB[v], quanta + 1e-3);
  }
}

TEST(CesiumTerrainServer, LevelZeroCarriesTheAvailabilityOfTheNextLevels) {
  Running s;
  const DecodedTile root = fetchTile(s, tileOfCentre(0));
  EXPECT_EQ(root.extensionOrder, (std::vector<int>{1, 2, 4}));
  const std::vector<std::uint8_t>& payload = root.extensions.at(4);
  ASSERT_GE(payload.size(), 4u);
  const std::uint32_t length = payload[0] | payload[1] << 8 | payload[2] << 16 |
                               static_cast<std::uint32_t>(payload[3]) << 24;
  ASSERT_EQ(length + 4u, payload.size());
  const auto metadata = nlohmann::json::parse(std::string(payload.begin() + 4, payload.end()));
  ASSERT_EQ(metadata["available"].size(), 10u);
  const Tms t10 = tileOfCentre(10);
  const auto& level10 = metadata["available"][9][0];
  EXPECT_LE(level10["startX"].get<std::int64_t>(), t10.x);
  EXPECT_GE(level10["endX"].get<std::int64_t>(), t10.x);
  EXPECT_LE(level10["startY"].get<std::int64_t>(), t10.y);
  EXPECT_GE(level10["endY"].get<std::int64_t>(), t10.y);
}

TEST(CesiumTerrainServer, OutsideTheWorldIsTheEllipsoidUnderWater) {
  Running s;
  const Tms t = tileOfCentre(8);
  const DecodedTile far = fetchTile(s, {t.z, t.x + 5, t.y});
  EXPECT_EQ(far.minimumHeight, 0.0f);
  EXPECT_EQ(far.maximumHeight, 0.0f);
  EXPECT_EQ(far.extensions.at(2), std::vector<std::uint8_t>{255});
  EXPECT_FALSE(far.west.empty());
}

TEST(CesiumTerrainServer, ExtensionsAndGzipAreNegotiatedAndCachedApart) {
  Running s;
  const Tms t = tileOfCentre(11);
  const HttpResponse plain = request(s.port(), t.path());
  const HttpResponse native = request(s.port(), t.path() + "?extensions=watermask");
  const HttpResponse zipped = request(s.port(), t.path(), "GET",
                                      std::string(kCesiumJsAccept) + "Accept-Encoding: gzip\r\n");
  ASSERT_EQ(plain.status, 200);
  ASSERT_EQ(native.status, 200);
  ASSERT_EQ(zipped.status, 200);
  EXPECT_TRUE(decodeQuantizedMesh(plain.body).extensionOrder.empty());
  EXPECT_EQ(decodeQuantizedMesh(native.body).extensionOrder, (std::vector<int>{2}));
  EXPECT_EQ(zipped.headers.at("content-encoding"), "gzip");
  const auto unzipped = gzip::decompress(zipped.body, 16u << 20);
  ASSERT_TRUE(unzipped.ok());
  EXPECT_EQ(decodeQuantizedMesh(unzipped.value()).extensionOrder, (std::vector<int>{1, 2}));
  std::set<std::string> etags{plain.headers.at("etag"), native.headers.at("etag"),
                              zipped.headers.at("etag")};
  EXPECT_EQ(etags.size(), 3u);
  const HttpResponse again = request(s.port(), t.path() + "?extensions=watermask", "GET",
                                     "If-None-Match: " + native.headers.at("etag") + "\r\n");
  EXPECT_EQ(again.status, 304);
  EXPECT_EQ(again.headers.at("vary"), "Accept, Accept-Encoding");
}

// tests/data/golden/island_cesium_12.terrain: the island's centre tile at level 12 with every
// extension, as served; STRAHLER_UPDATE_GOLDEN=1 rewrites it. Any change to the evaluation, the
// mesher or the format shows here.
TEST(CesiumTerrainServer, TheIslandsCentreTileIsTheGoldenOne) {
  Running s;
  const HttpResponse r = request(s.port(), tileOfCentre(12).path(), "GET", kCesiumJsAccept);
  ASSERT_EQ(r.status, 200);
  const std::filesystem::path path =
      std::filesystem::path(STRAHLER_TEST_DATA_DIR) / "golden" / "island_cesium_12.terrain";
  if (const char* update = std::getenv("STRAHLER_UPDATE_GOLDEN");
      update != nullptr && std::string(update) == "1") {
    std::ofstream(path, std::ios::binary) << r.body;
    GTEST_SKIP() << "rewrote " << path;
  }
  std::ifstream in(path, std::ios::binary);
  const std::string golden{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  ASSERT_FALSE(golden.empty()) << path;
  EXPECT_TRUE(r.body == golden) << "the tile differs from " << path << " (" << r.body.size()
                                << " bytes against " << golden.size() << ")";
}

TEST(CesiumTerrainServer, BadTerrainRequestsGetDefiniteAnswers) {
  Running s;
  const Tms t = tileOfCentre(5);
  const auto refused = [&](const std::string& path, int status, const std::string& message,
                           const std::string& headers = "") {
    test_support::expectRefused(s.port(), path, status, message, headers);
  };
  refused("/worlds/island/cesium/18/0/0.terrain", 404, "outside the grid (zoom 0..17)");
  refused("/worlds/island/cesium/0/2/0.terrain", 404, "tile 0/2/0 is outside the grid");
  refused("/worlds/island/cesium/1/0/2.terrain", 404, "tile 1/0/2 is outside the grid");
  refused("/worlds/island/cesium/0/0/x.terrain", 400, "'x' is not a non-negative integer");
  refused("/worlds/island/cesium/0/0/0.png", 400, "a Cesium terrain tile is named {y}.terrain");
  refused(t.path() + "?extensions=bogus", 400, "unknown quantized-mesh extension 'bogus'");
  refused(t.path(), 400, "unknown quantized-mesh extension 'vertexnormals'",
          "Accept: application/vnd.quantized-mesh;extensions=vertexnormals\r\n");
  refused(t.path() + "?size=5", 400, "unknown query parameter 'size'");
  refused("/worlds/island/tiles/0/0/0.terrain", 400, "Cesium terrain tiles are served under");
  refused("/worlds/nowhere/cesium/layer.json", 404, "unknown world 'nowhere'");
  EXPECT_EQ(request(s.port(), "/health").status, 200);
}

} // namespace
} // namespace strahler::app
