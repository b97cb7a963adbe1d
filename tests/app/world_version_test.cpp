// Caches never serve a stale world: every tile URL the server hands out (TileJSON of terrain,
// layers and vector tiles, Cesium's layer.json, the world document the pages build URLs from)
// carries the world's content version, as the viewer's rivers.geojson URL does; only a URL with the
// current version is immutable, and an ETag of another world's content is never answered 304. Over
// real sockets, with the world regenerated under the same id between two runs of the server.
#include "test_worlds.h"
#include "tile_server_harness.h"

#include "strahler/construction/world_builder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace strahler::app {
namespace {

using test_support::HttpResponse;
using test_support::request;
using test_support::Running;
using test_support::servedVersion;

constexpr const char* kImmutable = "public, max-age=86400, immutable";
constexpr const char* kRevalidate = "public, max-age=60, must-revalidate";

/// One tile of every kind, and the rivers the viewer reads, without a version.
const std::vector<std::string> kTiles = {"/worlds/island/rivers.geojson",
                                         "/worlds/island/tiles/12/1736/1494.png",
                                         "/worlds/island/tiles/12/1736/1494.relief",
                                         "/worlds/island/layers/slope/12/1736/1494.png",
                                         "/worlds/island/vector/12/1736/1494.mvt",
                                         "/worlds/island/vegetation/16/27796/23872.json",
                                         "/worlds/island/cesium/0/0/0.terrain",
                                         "/worlds/island/local/0/0/0.png"};

construction::WorldData island(std::uint64_t seed) {
  return construction::generateWorldData(strahler::test_support::defaultIslandSpec(seed), "k")
      .value();
}

/// Every tile URL the server tells a client to fetch, templates as given.
std::vector<std::string> handedOutTileUrls(std::uint16_t port) {
  std::vector<std::string> urls;
  for (const char* doc : {"/worlds/island/tilejson.json", "/worlds/island/vector/tilejson.json",
                          "/worlds/island/layers/slope/tilejson.json",
                          "/worlds/island/layers/vegetation/tilejson.json?species=bush"}) {
    const HttpResponse r = request(port, doc);
    EXPECT_EQ(r.status, 200) << doc << " " << r.body;
    const nlohmann::json tileJson = nlohmann::json::parse(r.body);
    for (const auto& url : tileJson["tiles"])
      urls.push_back(url.get<std::string>());
  }
  const auto layer = nlohmann::json::parse(request(port, "/worlds/island/cesium/layer.json").body);
  std::string cesium = layer["tiles"][0].get<std::string>();
  cesium.replace(cesium.find("{version}"), 9, layer["version"].get<std::string>());
  urls.push_back(cesium);
  return urls;
}

/// The URL of `path` as a client of the world's current version has it.
std::string current(std::uint16_t port, const std::string& path) {
  return test_support::versioned(port, path);
}

TEST(WorldVersion, EveryHandedOutTileUrlCarriesTheCurrentVersion) {
  Running s(island(1));
  const std::string version = servedVersion(s.port());
  ASSERT_EQ(version.size(), 16u) << version;
  const std::vector<std::string> urls = handedOutTileUrls(s.port());
  ASSERT_EQ(urls.size(), 5u);
  for (const std::string& url : urls)
    EXPECT_NE(url.find("v=" + version), std::string::npos) << url;
  // The layer's own parameters stay, the version comes after them.
  EXPECT_NE(urls[3].find("?species=bush&v=" + version), std::string::npos) << urls[3];
}

TEST(WorldVersion, OnlyTheCurrentVersionIsImmutableAndTheEtagFollowsTheContent) {
  Running s(island(1));
  for (const std::string& path : kTiles) {
    const HttpResponse versioned = request(s.port(), current(s.port(), path));
    ASSERT_EQ(versioned.status, 200) << path << " " << versioned.body;
    EXPECT_EQ(versioned.headers.at("cache-control"), kImmutable) << path;
    for (const std::string& other :
         {path, path + (path.find('?') == std::string::npos ? "?" : "&") + "v=0000000000000000"}) {
      const HttpResponse r = request(s.port(), other);
      ASSERT_EQ(r.status, 200) << other;
      EXPECT_EQ(r.headers.at("cache-control"), kRevalidate) << other;
      EXPECT_EQ(r.headers.at("etag"), versioned.headers.at("etag")) << other;
      EXPECT_EQ(r.body, versioned.body) << other;
      // The same content: revalidation succeeds, and says again to revalidate.
      const HttpResponse again =
          request(s.port(), other, "GET", "If-None-Match: " + r.headers.at("etag") + "\r\n");
      EXPECT_EQ(again.status, 304) << other;
      EXPECT_EQ(again.headers.at("cache-control"), kRevalidate) << other;
    }
  }
}

TEST(WorldVersion, ARegeneratedWorldHasNewUrlsAndNoOldEtagGets304) {
  std::string oldVersion;
  std::vector<std::string> oldUrls, oldEtags, oldBodies;
  {
    Running first(island(1));
    oldVersion = servedVersion(first.port());
    oldUrls = handedOutTileUrls(first.port());
    for (const std::string& path : kTiles) {
      const HttpResponse r = request(first.port(), current(first.port(), path));
      ASSERT_EQ(r.status, 200) << path;
      oldEtags.push_back(r.headers.at("etag"));
      oldBodies.push_back(r.body);
    }
  }
  // The same world id, another content: the server restarted over a regenerated world.
  Running second(island(2));
  const std::string newVersion = servedVersion(second.port());
  EXPECT_NE(newVersion, oldVersion);
  const std::vector<std::string> newUrls = handedOutTileUrls(second.port());
  ASSERT_EQ(newUrls.size(), oldUrls.size());
  for (std::size_t i = 0; i < newUrls.size(); ++i) {
    EXPECT_NE(newUrls[i], oldUrls[i]);
    EXPECT_NE(newUrls[i].find("v=" + newVersion), std::string::npos) << newUrls[i];
  }
  int changedBodies = 0;
  for (std::size_t i = 0; i < kTiles.size(); ++i) {
    const std::string& path = kTiles[i];
    const HttpResponse fresh = request(second.port(), current(second.port(), path));
    ASSERT_EQ(fresh.status, 200) << path;
    EXPECT_EQ(fresh.headers.at("cache-control"), kImmutable) << path;
    EXPECT_NE(fresh.headers.at("etag"), oldEtags[i]) << path;
    changedBodies += fresh.body != oldBodies[i];
    // A cache holding the old world revalidates by the old URL (or none): it gets the new
    // bytes, never a 304, and may keep them only briefly.
    for (const std::string& stale : {path + "?v=" + oldVersion, path}) {
      const HttpResponse r =
          request(second.port(), stale, "GET", "If-None-Match: " + oldEtags[i] + "\r\n");
      EXPECT_EQ(r.status, 200) << stale;
      EXPECT_EQ(r.body, fresh.body) << stale;
      EXPECT_EQ(r.headers.at("etag"), fresh.headers.at("etag")) << stale;
      EXPECT_EQ(r.headers.at("cache-control"), kRevalidate) << stale;
    }
  }
  EXPECT_GE(changedBodies, 5) << "the two seeds should give other terrain";
}

TEST(WorldVersion, TheSameWorldFromAnotherGeneratorVersionIsAnotherVersion) {
  // A world file regenerated by another generator version under the same name: even where
  // its relief came out the same, it is another file, so another version.
  construction::WorldData world = island(1);
  construction::WorldData other = world;
  other.generatorVersion = "strahler-generator-next";
  std::string before, after;
  {
    Running s(std::move(world));
    before = servedVersion(s.port());
  }
  {
    Running s(std::move(other));
    after = servedVersion(s.port());
  }
  EXPECT_EQ(before.size(), 16u);
  EXPECT_NE(before, after);
}

} // namespace
} // namespace strahler::app
