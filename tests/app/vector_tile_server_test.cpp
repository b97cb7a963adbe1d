// Vector tiles (.mvt) over real sockets: headers, gzip, ETag/304, TileJSON, bad input, the
// layers' contents, and contours that meet across tile edges.
#include "gzip.h"
#include "result_matchers.h"
#include "router.h"
#include "tile_request.h"
#include "tile_server_harness.h"
#include "vector_layers.h"
#include "web_tile_route.h"

#include "strahler/geometry/web_mercator.h"
#include "strahler/vector_tile/vector_tile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace strahler::app {
namespace {

using test_support::HttpResponse;
using test_support::request;
using test_support::Running;
using vector_tile::GeometryType;
using vector_tile::Point;

/// A z12 tile over the island's hills (its east and south neighbours are hilly too).
constexpr geometry::TileId kHills{12, 1736, 1494};
/// A z10 tile over the island with its coast.
constexpr geometry::TileId kCoast{10, 434, 373};

std::string path(const geometry::TileId& t) {
  return "/worlds/island/vector/" + std::to_string(t.z) + "/" + std::to_string(t.x) + "/" +
         std::to_string(t.y) + ".mvt";
}

const vector_tile::Layer* layerOf(const vector_tile::Tile& tile, const std::string& name) {
  for (const auto& layer : tile.layers)
    if (layer.name == name)
      return &layer;
  return nullptr;
}

template <class T> T property(const vector_tile::Feature& f, const std::string& key) {
  for (const auto& [k, v] : f.properties)
    if (k == key && std::holds_alternative<T>(v))
      return std::get<T>(v);
  ADD_FAILURE() << "no " << key;
  return T{};
}

vector_tile::Tile fetch(const Running& s, const geometry::TileId& t) {
  const HttpResponse r = request(s.port(), path(t));
  EXPECT_EQ(r.status, 200) << path(t) << " " << r.body;
  auto tile = vector_tile::decodeTile(r.body);
  EXPECT_TRUE(tile.ok()) << path(t);
  return tile.ok() ? tile.value() : vector_tile::Tile{};
}

TEST(VectorTileRoute, TheRouterAndTheParserNameTheTileAndItsCoding) {
  EXPECT_EQ(routeOf({"worlds", "w", "vector", "tilejson.json"}).endpoint,
            Endpoint::kVectorTileJson);
  EXPECT_EQ(routeOf({"worlds", "w", "vector", "1", "2", "3.mvt"}).endpoint, Endpoint::kVectorTile);
  EXPECT_EQ(routeOf({"worlds", "w", "vector", "other.json"}).endpoint, Endpoint::kNoSuchResource);
  const std::vector<std::string> s = {"worlds", "w", "vector", "12", "1736", "1494.mvt"};
  STRAHLER_ASSIGN_OR_ASSERT(const TileRequest plain, parseVectorTileRoute("w", s, {}, ""));
  STRAHLER_ASSIGN_OR_ASSERT(const TileRequest zipped,
                            parseVectorTileRoute("w", s, {}, "br, gzip;q=0.5"));
  EXPECT_EQ(plain.kind(), TileKind::kVector);
  EXPECT_EQ(plain.scheme, tiling::SchemeKind::kWebMercator);
  EXPECT_EQ(plain.tile, kHills);
  EXPECT_FALSE(plain.options.gzip);
  EXPECT_TRUE(zipped.options.gzip);
  EXPECT_EQ(tileKey(plain), "w|tiles|12|1736|1494|mvt|0|id");
  EXPECT_EQ(tileKey(zipped), "w|tiles|12|1736|1494|mvt|0|gz");
  EXPECT_FALSE(parseVectorTileRoute("w", s, {{"v", "1"}}, "").ok());
}

TEST(VectorTileServer, ATileIsAnMvtWithTheTilePipelinesHeaders) {
  Running s;
  HttpResponse r = request(s.port(), path(kHills));
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.headers["content-type"], "application/vnd.mapbox-vector-tile");
  EXPECT_EQ(r.headers["access-control-allow-origin"], "*");
  EXPECT_EQ(r.headers["vary"], "Accept-Encoding");
  EXPECT_EQ(r.headers.count("content-encoding"), 0u);
  ASSERT_FALSE(r.headers["etag"].empty());
  STRAHLER_ASSIGN_OR_ASSERT(const vector_tile::Tile tile, vector_tile::decodeTile(r.body));
  for (const char* name : {"contours", "rivers"})
    EXPECT_NE(layerOf(tile, name), nullptr) << name;
  HttpResponse again =
      request(s.port(), path(kHills), "GET", "If-None-Match: " + r.headers["etag"] + "\r\n");
  EXPECT_EQ(again.status, 304);
  EXPECT_EQ(again.headers["vary"], "Accept-Encoding");
  EXPECT_EQ(request(s.port(), path(kHills), "HEAD").status, 200);
}

TEST(VectorTileServer, GzipIsAContentEncodingOnlyForClientsThatAcceptIt) {
  Running s;
  HttpResponse plain = request(s.port(), path(kCoast));
  HttpResponse zipped = request(s.port(), path(kCoast), "GET", "Accept-Encoding: gzip\r\n");
  ASSERT_EQ(plain.status, 200);
  ASSERT_EQ(zipped.status, 200);
  EXPECT_EQ(zipped.headers["content-encoding"], "gzip");
  EXPECT_LT(zipped.body.size(), plain.body.size());
  const auto unzipped = gzip::decompress(zipped.body, 16u << 20);
  ASSERT_TRUE(unzipped.ok());
  EXPECT_TRUE(unzipped.value() == plain.body);
  EXPECT_NE(zipped.headers["etag"], plain.headers["etag"]);
  EXPECT_EQ(request(s.port(), path(kCoast), "GET",
                    "Accept-Encoding: gzip\r\nIf-None-Match: " + zipped.headers["etag"] + "\r\n")
                .status,
            304);
}

TEST(VectorTileServer, TileJsonListsTheVectorLayers) {
  Running s;
  HttpResponse r = request(s.port(), "/worlds/island/vector/tilejson.json");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.headers["content-type"], "application/json");
  const auto tj = nlohmann::json::parse(r.body);
  EXPECT_EQ(tj["tilejson"], "3.0.0");
  const std::string url = tj["tiles"][0];
  EXPECT_NE(url.find("/worlds/island/vector/{z}/{x}/{y}.mvt"), std::string::npos) << url;
  std::map<std::string, nlohmann::json> layers;
  for (const auto& layer : tj["vector_layers"])
    layers[layer["id"]] = layer;
  for (const char* id : {"water", "contours", "rivers", "features"}) {
    ASSERT_EQ(layers.count(id), 1u) << id;
    EXPECT_TRUE(layers[id]["fields"].is_object()) << id;
    EXPECT_EQ(layers[id]["minzoom"], 0) << id;
    EXPECT_EQ(layers[id]["maxzoom"], tiling::TileScheme::kMaxWebZoom) << id;
  }
  EXPECT_TRUE(layers["rivers"]["fields"].contains("rosgen"));
  EXPECT_TRUE(layers["contours"]["fields"].contains("index"));
}

TEST(VectorTileServer, BadVectorRequestsGetDefiniteAnswers) {
  Running s;
  const auto refused = [&](const std::string& path, int status, const std::string& message) {
    test_support::expectRefused(s.port(), path, status, message);
  };
  refused("/worlds/island/vector/19/0/0.mvt", 404, "tile 19/0/0 is outside the grid");
  refused("/worlds/island/vector/2/4/0.mvt", 404, "tile 2/4/0 is outside the grid");
  refused("/worlds/island/vector/0/0/x.mvt", 400, "'x' is not a non-negative integer");
  refused("/worlds/island/vector/0/0/00.mvt", 400, "'00' has a leading zero");
  refused("/worlds/island/vector/0/0/0.png", 400, "a vector tile is named {y}.mvt");
  refused("/worlds/island/vector/0/0/0.mvt?size=512", 400, "unknown query parameter 'size'");
  refused("/worlds/island/tiles/0/0/0.mvt", 400, "vector tiles are served under");
  refused("/worlds/island/local/0/0/0.mvt", 400, "vector tiles are served under");
  refused("/worlds/island/vector/0/0.mvt", 404, "no such resource under /worlds/island");
  refused("/worlds/nowhere/vector/0/0/0.mvt", 404, "unknown world 'nowhere'");
}

TEST(VectorTileServer, LayersCarryTheirAttributesAndStayInTheBuffer) {
  Running s;
  const vector_tile::Tile tile = fetch(s, kCoast);
  const int lo = -kVectorBuffer, hi = static_cast<int>(vector_tile::kDefaultExtent) + kVectorBuffer;
  for (const auto& layer : tile.layers)
    for (const auto& f : layer.features)
      for (const auto& part : f.parts)
        for (const Point p : part)
          ASSERT_TRUE(p.x >= lo && p.x <= hi && p.y >= lo && p.y <= hi) << layer.name;
  const auto* rivers = layerOf(tile, "rivers");
  ASSERT_NE(rivers, nullptr);
  const int minOrder = minRiverOrder(kCoast.z, 99);
  for (const auto& f : rivers->features) {
    EXPECT_EQ(f.type, GeometryType::kLineString);
    EXPECT_GE(property<std::int64_t>(f, "order"), minOrder);
    EXPECT_GT(property<double>(f, "flow"), 0.0);
    EXPECT_GT(property<double>(f, "width"), 0.0);
    EXPECT_FALSE(property<std::string>(f, "rosgen").empty());
  }
  const auto* contours = layerOf(tile, "contours");
  ASSERT_NE(contours, nullptr);
  bool anyIndex = false;
  for (const auto& f : contours->features) {
    const auto elevation = property<std::int64_t>(f, "elevation");
    EXPECT_EQ(elevation % static_cast<std::int64_t>(contourInterval(kCoast.z)), 0);
    EXPECT_GT(elevation, 0);
    anyIndex |= property<bool>(f, "index");
  }
  EXPECT_TRUE(anyIndex);
  const auto* water = layerOf(tile, "water");
  ASSERT_NE(water, nullptr); // the coast tile has sea
  for (const auto& f : water->features) {
    EXPECT_EQ(f.type, GeometryType::kPolygon);
    ASSERT_FALSE(f.parts.empty());
    EXPECT_GT(vector_tile::ringArea2(f.parts.front()), 0); // an exterior ring first
  }
}

/// The points where the contours of `tile` cross the line x = `at` (or y = `at` when
/// `horizontal`), by elevation: the other coordinate of each crossing.
std::map<std::int64_t, std::vector<double>> crossings(const vector_tile::Tile& tile, int at,
                                                      bool horizontal = false) {
  std::map<std::int64_t, std::vector<double>> out;
  const auto* contours = layerOf(tile, "contours");
  if (contours == nullptr)
    return out;
  for (const auto& f : contours->features)
    for (const auto& part : f.parts)
      for (std::size_t i = 0; i + 1 < part.size(); ++i) {
        Point a = part[i], b = part[i + 1];
        if (horizontal) {
          a = {a.y, a.x};
          b = {b.y, b.x};
        }
        if ((a.x < at) == (b.x < at))
          continue;
        const double t = static_cast<double>(at - a.x) / (b.x - a.x);
        out[property<std::int64_t>(f, "elevation")].push_back(a.y + t * (b.y - a.y));
      }
  return out;
}

/// The number of crossings of `first`'s that `second` has within a unit; fails on any other.
std::size_t expectSameCrossings(const std::map<std::int64_t, std::vector<double>>& fromWest,
                                const std::map<std::int64_t, std::vector<double>>& fromEast) {
  std::size_t checked = 0;
  for (const auto& [elevation, ys] : fromWest) {
    if (fromEast.count(elevation) == 0) {
      ADD_FAILURE() << "no contour at " << elevation << " on the other side";
      continue;
    }
    for (const double y : ys) {
      double nearest = 1e9;
      for (const double other : fromEast.at(elevation))
        nearest = std::min(nearest, std::abs(other - y));
      EXPECT_LT(nearest, 1.0) << "elevation " << elevation << " at " << y;
      ++checked;
    }
  }
  EXPECT_EQ(fromWest.size(), fromEast.size());
  return checked;
}

TEST(VectorTileServer, ContoursOfNeighboursMeetAtTheirSharedEdge) {
  Running s;
  const int extent = static_cast<int>(vector_tile::kDefaultExtent);
  const vector_tile::Tile tile = fetch(s, kHills);
  const vector_tile::Tile east = fetch(s, {kHills.z, kHills.x + 1, kHills.y});
  const vector_tile::Tile south = fetch(s, {kHills.z, kHills.x, kHills.y + 1});
  // The edges are hilly: seam checks that check something.
  EXPECT_GE(expectSameCrossings(crossings(tile, extent), crossings(east, 0)), 3u);
  EXPECT_GE(expectSameCrossings(crossings(east, 0), crossings(tile, extent)), 3u);
  EXPECT_GE(expectSameCrossings(crossings(tile, extent, true), crossings(south, 0, true)), 3u);
}

// tests/data/golden/island_vector_12.mvt: the hills' tile as served (not gzipped);
// STRAHLER_UPDATE_GOLDEN=1 rewrites it. Any change to the evaluation, the layers or the
// encoding shows here; two servers over the same world send the same bytes.
TEST(VectorTileServer, TheHillsTileIsTheGoldenOne) {
  Running s;
  const HttpResponse r = request(s.port(), path(kHills));
  ASSERT_EQ(r.status, 200);
  {
    Running other;
    EXPECT_TRUE(request(other.port(), path(kHills)).body == r.body) << "not deterministic";
  }
  const std::filesystem::path golden =
      std::filesystem::path(STRAHLER_TEST_DATA_DIR) / "golden" / "island_vector_12.mvt";
  if (const char* update = std::getenv("STRAHLER_UPDATE_GOLDEN");
      update != nullptr && std::string(update) == "1") {
    std::ofstream(golden, std::ios::binary) << r.body;
    GTEST_SKIP() << "rewrote " << golden;
  }
  std::ifstream in(golden, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  ASSERT_FALSE(bytes.empty()) << golden;
  EXPECT_TRUE(r.body == bytes) << "the tile differs from " << golden << " (" << r.body.size()
                               << " bytes against " << bytes.size() << ")";
}

/// Longitude/latitude of the point (u, v) of `tile` (0..1 from its north-west corner).
geometry::Vec2 lonLatIn(const geometry::TileId& tile, double u, double v) {
  const double n = std::ldexp(1.0, tile.z);
  const double mx = (static_cast<double>(tile.x) + u) / n,
               my = (static_cast<double>(tile.y) + v) / n;
  return {mx * 360.0 - 180.0,
          std::atan(std::sinh(std::numbers::pi * (1.0 - 2.0 * my))) * 180.0 / std::numbers::pi};
}

TEST(VectorLayers, TheArtistsMapIsTheFeaturesLayerWhereItWasDrawn) {
  input::Features drawn;
  drawn.mountains.push_back({lonLatIn(kHills, 0.5, 0.25), {}, 1200.0, std::nullopt});
  drawn.mountains.push_back({lonLatIn(kHills, 3.0, 0.5), {}, std::nullopt, std::nullopt});
  drawn.rivers.push_back(
      {{lonLatIn(kHills, -1.0, 0.5), lonLatIn(kHills, 2.0, 0.5)}, {}, "Long River"});
  WorldVectors world;
  world.features = &drawn;
  const vector_tile::Layer layer = featuresLayer(world, kHills);
  ASSERT_EQ(layer.features.size(), 2u); // the second mountain is in another tile
  const auto& mountain = layer.features[0];
  EXPECT_EQ(mountain.type, GeometryType::kPoint);
  EXPECT_EQ(mountain.parts, (std::vector<std::vector<Point>>{{{2048, 1024}}}));
  EXPECT_EQ(property<std::string>(mountain, "kind"), "mountain");
  EXPECT_EQ(property<double>(mountain, "elevation"), 1200.0);
  const auto& river = layer.features[1];
  EXPECT_EQ(property<std::string>(river, "name"), "Long River");
  ASSERT_EQ(river.parts.size(), 1u);
  EXPECT_EQ(river.parts[0].front(), (Point{-kVectorBuffer, 2048})); // clipped at the buffer
  EXPECT_EQ(river.parts[0].back(), (Point{4096 + kVectorBuffer, 2048}));
}

TEST(VectorLayers, OnlyTheOrdersVisibleAtTheZoomAreDrawn) {
  EXPECT_EQ(minRiverOrder(14, 6), 1);
  EXPECT_EQ(minRiverOrder(12, 6), 1);
  EXPECT_EQ(minRiverOrder(10, 6), 3);
  EXPECT_EQ(minRiverOrder(3, 6), 6); // the world's main rivers at every zoom
  WorldVectors world;
  world.maxOrder = 5;
  for (int order = 1; order <= 5; ++order) {
    MercatorRiver river;
    river.order = order;
    river.flow = river.width = 1.0;
    for (const double u : {0.1, 0.9}) {
      const geometry::Vec2 ll = lonLatIn(kCoast, u, 0.1 * order);
      river.line.points.push_back(geometry::webMercatorUnit(ll));
      river.line.box.add(river.line.points.back());
    }
    world.rivers.push_back(river);
  }
  const vector_tile::Layer layer = riversLayer(world, kCoast); // zoom 10: orders 3 and up
  ASSERT_EQ(layer.features.size(), 3u);
  for (const auto& f : layer.features) {
    const std::int64_t order = property<std::int64_t>(f, "order");
    EXPECT_GE(order, 3);
    const int y = static_cast<int>(std::lround(0.1 * static_cast<double>(order) * 4096.0));
    EXPECT_EQ(f.parts, (std::vector<std::vector<Point>>{{{410, y}, {3686, y}}}));
  }
}

} // namespace
} // namespace strahler::app
