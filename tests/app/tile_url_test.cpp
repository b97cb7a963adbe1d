// Tile URLs have one spelling, and their errors name only what works at that path: an unknown
// extension under /tiles/ or /local/ lists the formats served there (each of which then gives
// 200), and a trailing slash is 404, never the same tile.
#include "result_matchers.h"
#include "route_parser.h"
#include "tile_server_harness.h"

#include <gtest/gtest.h>

#include <string>

namespace strahler::app {
namespace {

using test_support::request;
using test_support::Running;

TEST(TileUrls, AnUnknownExtensionListsOnlyTheFormatsServedAtThatPath) {
  Running s;
  for (const std::string path : {"/worlds/island/tiles/10/433/373", "/worlds/island/local/2/1/2"}) {
    const auto refused = request(s.port(), path + ".jpg");
    EXPECT_EQ(refused.status, 400) << path;
    const std::string under = path.find("/local/") != std::string::npos ? "local" : "tiles";
    EXPECT_NE(refused.body.find("unknown tile format 'jpg' (under /" + under +
                                "/: png, terrarium, png16, tif, exr, drc, glb or relief)"),
              std::string::npos)
        << refused.body;
    for (const char* elsewhere : {"terrain", "mvt", "json"})
      EXPECT_EQ(refused.body.find(elsewhere), std::string::npos) << elsewhere << refused.body;
    // Every format the message names is served there (small sizes: quick to compute).
    int served = 0;
    for (const std::string format :
         {"png", "terrarium", "png16", "tif", "exr", "drc", "glb", "relief"}) {
      const bool mesh = format == "drc" || format == "glb";
      const auto r = request(s.port(), path + "." + format + (mesh ? "?size=4" : "?size=16"));
      EXPECT_EQ(r.status, 200) << path << "." << format << " " << r.body;
      ++served;
    }
    EXPECT_EQ(served, 8);
  }
}

TEST(TileUrls, ATrailingSlashIsNotFoundNeverTheSameTile) {
  Running s;
  const std::string tile = "/worlds/island/tiles/10/433/373.png";
  const auto real = request(s.port(), tile);
  ASSERT_EQ(real.status, 200);
  for (const std::string& target :
       {tile + "/", tile + "/?size=256", std::string("/worlds/island/"),
        std::string("/worlds/island/cesium/layer.json/"), std::string("/health/")}) {
    const auto r = request(s.port(), target);
    EXPECT_EQ(r.status, 404) << target;
    EXPECT_EQ(r.headers.count("etag"), 0u) << target;
    EXPECT_NE(r.body.find("ends with '/'; resources are named without it"), std::string::npos)
        << target << " " << r.body;
  }
  EXPECT_EQ(request(s.port(), "/").status, 200); // the root is "/" itself
}

TEST(TileUrls, TheParserSaysWhenAPathEndsWithASlash) {
  EXPECT_TRUE(strahler::test_support::valueOf(parseTarget("/worlds/")).trailingSlash);
  EXPECT_TRUE(strahler::test_support::valueOf(parseTarget("/a/b.png/?size=1")).trailingSlash);
  EXPECT_FALSE(strahler::test_support::valueOf(parseTarget("/a/b.png?x=/")).trailingSlash);
  EXPECT_FALSE(strahler::test_support::valueOf(parseTarget("/")).trailingSlash);
}

} // namespace
} // namespace strahler::app
