// The server's answers that do not depend on a world: the work gauges of /metrics, the
// viewer's static files, and the JSON list of worlds.
#include "server_gauges.h"
#include "static_files.h"
#include "world_documents.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace strahler::app {
namespace {

TEST(WorkGauges, EachValueIsItsOwnGauge) {
  WorkGauges g;
  g.cache.hits = 11;
  g.cache.misses = 12;
  g.cache.evictions = 13;
  g.cache.bytes = 14;
  g.cache.entries = 15;
  g.cache.inFlight = 16;
  g.cache.computations = 17;
  g.cache.coalesced = 18;
  g.cache.cancelled = 19;
  g.cacheMaxBytes = 20;
  g.queued = 21;
  g.busy = 22;
  const std::string text = renderWorkGauges(g);
  for (const char* line :
       {"strahler_tile_cache_hits_total 11.000000\n",
        "strahler_tile_cache_misses_total 12.000000\n",
        "strahler_tile_cache_evictions_total 13.000000\n", "strahler_tile_cache_bytes 14.000000\n",
        "strahler_tile_cache_entries 15.000000\n", "strahler_tiles_in_flight 16.000000\n",
        "strahler_tile_computations_total 17.000000\n",
        "strahler_tile_requests_coalesced_total 18.000000\n",
        "strahler_tile_computations_cancelled_total 19.000000\n",
        "strahler_tile_cache_max_bytes 20.000000\n", "strahler_worker_queue_depth 21.000000\n",
        "strahler_workers_busy 22.000000\n", "# TYPE strahler_tile_cache_hits_total counter\n",
        "# TYPE strahler_tile_cache_bytes gauge\n"})
    EXPECT_NE(text.find(line), std::string::npos) << line;
}

/// A scratch web root with index.html, app.js and notes.txt; removed at the end.
struct WebRoot {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("strahler-web-" + std::to_string(::getpid()));
  WebRoot() {
    std::filesystem::create_directories(dir / "assets");
    std::ofstream(dir / "index.html") << "<html>viewer</html>";
    std::ofstream(dir / "assets" / "app.js") << "let x = 1;";
    std::ofstream(dir / "assets" / "water.jpg") << "jpeg"; // CesiumJS's textures
    std::ofstream(dir / "notes.txt") << "private";
  }
  ~WebRoot() { std::filesystem::remove_all(dir); }
};

TEST(StaticFiles, ServesTheViewersFilesWithTheirTypesOnly) {
  const WebRoot root;
  const http::Response js = staticFile(root.dir.string(), {"assets", "app.js"});
  EXPECT_EQ(js.status, 200);
  EXPECT_EQ(js.body, "let x = 1;");
  EXPECT_EQ(js.route, "static");
  ASSERT_FALSE(js.headers.empty());
  EXPECT_EQ(js.headers[0].second, "text/javascript");
  const http::Response jpeg = staticFile(root.dir.string(), {"assets", "water.jpg"});
  EXPECT_EQ(jpeg.status, 200);
  ASSERT_FALSE(jpeg.headers.empty());
  EXPECT_EQ(jpeg.headers[0].second, "image/jpeg");
  EXPECT_EQ(staticFile(root.dir.string(), {"notes.txt"}).status, 404); // not a viewer type
  EXPECT_EQ(staticFile(root.dir.string(), {"missing.js"}).status, 404);
  EXPECT_EQ(staticFile(root.dir.string(), {"assets"}).status, 404); // a folder
  EXPECT_EQ(staticFile("", {"index.html"}).status, 404);            // no viewer
}

TEST(StaticFiles, TheIndexIsTheViewerElseAListOfWorlds) {
  const WebRoot root;
  const http::Response viewer = indexPage(root.dir.string(), {"a"});
  EXPECT_EQ(viewer.status, 200);
  EXPECT_EQ(viewer.body, "<html>viewer</html>");
  EXPECT_EQ(viewer.route, "viewer");
  const http::Response list = indexPage("", {"a", "b"});
  EXPECT_EQ(list.status, 200);
  EXPECT_EQ(list.route, "viewer");
  EXPECT_NE(list.body.find("<a href=\"/worlds/a/tilejson.json\">"), std::string::npos);
  EXPECT_NE(list.body.find("<a href=\"/worlds/b/rivers.geojson\">"), std::string::npos);
}

TEST(WorldDocuments, TheListIsTheJsonArrayOfTheMetadata) {
  const std::string a = R"({"id":"a","seed":1})", b = R"({"id":"b","seed":2})";
  const std::string list = worldListJson({&a, &b});
  EXPECT_EQ(list,
            nlohmann::json::array({nlohmann::json::parse(a), nlohmann::json::parse(b)}).dump());
  EXPECT_EQ(worldListJson({}), "[]");
  EXPECT_EQ(healthJson(2), R"({"status":"ok","worlds":2})");
}

} // namespace
} // namespace strahler::app
