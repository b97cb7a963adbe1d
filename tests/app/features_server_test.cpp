// GET /worlds/{id}/features.geojson over real sockets: the artist's vector map as drawn, and an
// empty FeatureCollection for a world without one.
#include "tile_server_harness.h"
#include "world_documents.h"

#include "strahler/construction/world_builder.h"
#include "strahler/http/http_server.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace strahler::app {
namespace {

using nlohmann::json;
using test_support::request;
using test_support::Running;

input::Features drawnFeatures() {
  input::Features f;
  f.mountains.push_back({{8.9456, 42.3797}, {0.0, 0.0}, 2706.0, 4000.0});
  f.mountains.push_back({{9.0567, 42.2178}, {1.0, 1.0}, std::nullopt, std::nullopt});
  f.ridges.push_back({{{8.83, 42.44}, {8.95, 42.38}}, {{0.0, 0.0}, {1.0, 1.0}}, 1800.0});
  f.rivers.push_back({{{9.04, 42.28}, {9.531, 42.547}}, {{0.0, 0.0}, {1.0, 1.0}}, "Golo"});
  f.rivers.push_back({{{9.12, 42.27}, {9.5451, 42.1032}}, {{0.0, 0.0}, {1.0, 1.0}}, ""});
  return f;
}

/// A server of one world (the default island) whose features are `features`.
struct DrawnServer {
  TileServer tiles;
  http::Server server;
  explicit DrawnServer(const input::Features& features)
      : tiles({{"drawn", withFeatures(features)}}, Running::serverOptions(16u << 20, "")),
        server(
            Running::options({}),
            [this](const http::Request& r, std::function<void(http::Response)> done) {
              tiles.handle(r, std::move(done));
            },
            [this](const std::string& route, int status, std::size_t bytes, double ms) {
              tiles.observe(route, status, bytes, ms);
            }) {
    EXPECT_TRUE(server.start().ok());
  }
  static construction::WorldData withFeatures(const input::Features& features) {
    construction::WorldData data =
        construction::generateWorldData(strahler::test_support::defaultIslandSpec(), "k").value();
    data.features = features;
    return data;
  }
};

TEST(FeaturesEndpoint, ServesTheFeaturesAsDrawn) {
  DrawnServer s(drawnFeatures());
  const auto r = request(s.server.port(), "/worlds/drawn/features.geojson");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.headers.at("content-type"), "application/geo+json");
  const json doc = json::parse(r.body);
  EXPECT_EQ(doc["type"], "FeatureCollection");
  const json& list = doc["features"];
  ASSERT_EQ(list.size(), 5u);
  EXPECT_EQ(list[0]["properties"],
            (json{{"kind", "mountain"}, {"elevation", 2706.0}, {"radius", 4000.0}}));
  EXPECT_EQ(list[0]["geometry"], (json{{"type", "Point"}, {"coordinates", {8.9456, 42.3797}}}));
  EXPECT_EQ(list[1]["properties"], (json{{"kind", "mountain"}}));
  EXPECT_EQ(list[2]["properties"], (json{{"kind", "ridge"}, {"elevation", 1800.0}}));
  EXPECT_EQ(list[2]["geometry"]["type"], "LineString");
  EXPECT_EQ(list[2]["geometry"]["coordinates"], (json{{8.83, 42.44}, {8.95, 42.38}}));
  EXPECT_EQ(list[3]["properties"], (json{{"kind", "river"}, {"name", "Golo"}}));
  EXPECT_EQ(list[3]["geometry"]["coordinates"], (json{{9.04, 42.28}, {9.531, 42.547}}));
  EXPECT_EQ(list[4]["properties"], (json{{"kind", "river"}}));
  // Read back as the numbers that were drawn, exactly.
  EXPECT_EQ(list[4]["geometry"]["coordinates"][1][0].get<double>(), 9.5451);
  EXPECT_EQ(request(s.server.port(), "/worlds/other/features.geojson").status, 404);
}

TEST(FeaturesEndpoint, AWorldWithoutFeaturesHasAnEmptyCollection) {
  Running s;
  const auto r = request(s.port(), "/worlds/island/features.geojson");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.headers.at("content-type"), "application/geo+json");
  EXPECT_EQ(json::parse(r.body),
            (json{{"type", "FeatureCollection"}, {"features", json::array()}}));
}

TEST(FeaturesEndpoint, InvalidUtf8InANameIsReplaced) {
  input::Features f;
  f.rivers.push_back({{{9.0, 42.0}, {9.1, 42.1}}, {{0.0, 0.0}, {1.0, 1.0}}, "A\xff"});
  const json doc = json::parse(featuresGeoJson(f));
  EXPECT_EQ(doc["features"][0]["properties"]["name"], "A\xef\xbf\xbd");
}

} // namespace
} // namespace strahler::app
