// The router tells the endpoints of the server contract apart by the shape of the path.
#include "router.h"
#include "tile_service.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace strahler::app {
namespace {

TEST(Router, EachPathShapeNamesItsEndpoint) {
  using S = std::vector<std::string>;
  const struct {
    S segments;
    Endpoint endpoint;
    std::string world;
  } cases[] = {
      {S{}, Endpoint::kIndex, ""},
      {S{"game"}, Endpoint::kGame, ""},
      {S{"cesium"}, Endpoint::kCesium, ""},
      {S{"health"}, Endpoint::kHealth, ""},
      {S{"metrics"}, Endpoint::kMetrics, ""},
      {S{"worlds"}, Endpoint::kWorldList, ""},
      {S{"worlds", "a"}, Endpoint::kWorld, "a"},
      {S{"worlds", "a", "tilejson.json"}, Endpoint::kTileJson, "a"},
      {S{"worlds", "a", "rivers.geojson"}, Endpoint::kRivers, "a"},
      {S{"worlds", "a", "features.geojson"}, Endpoint::kFeatures, "a"},
      {S{"worlds", "a", "tiles", "1", "2", "3.png"}, Endpoint::kTile, "a"},
      {S{"worlds", "a", "local", "1", "2", "3.glb"}, Endpoint::kTile, "a"},
      {S{"worlds", "a", "other", "1", "2", "3.png"}, Endpoint::kNoSuchResource, "a"},
      {S{"worlds", "a", "tiles", "1", "2"}, Endpoint::kNoSuchResource, "a"},
      {S{"worlds", "a", "metadata"}, Endpoint::kNoSuchResource, "a"},
      {S{"index.html"}, Endpoint::kStaticFile, ""},
      {S{"assets", "viewer.js"}, Endpoint::kStaticFile, ""},
      {S{"health", "x"}, Endpoint::kStaticFile, ""},
  };
  for (const auto& c : cases) {
    const Route route = routeOf(c.segments);
    const std::string path = c.segments.empty() ? "/" : "/" + c.segments[0] + "/...";
    EXPECT_EQ(route.endpoint, c.endpoint) << path << " (" << c.segments.size() << " segments)";
    EXPECT_EQ(route.world, c.world) << path;
  }
}

TEST(TileService, RenderErrorsReportTheirOutcome) {
  EXPECT_EQ(renderStatus(base::ErrorCode::kNotFound), service::TileStatus::kNotFound);
  EXPECT_EQ(renderStatus(base::ErrorCode::kUnsupported), service::TileStatus::kUnsupported);
  EXPECT_EQ(renderStatus(base::ErrorCode::kOutOfRange), service::TileStatus::kFailed);
  EXPECT_EQ(renderStatus(base::ErrorCode::kInternal), service::TileStatus::kFailed);
}

} // namespace
} // namespace strahler::app
