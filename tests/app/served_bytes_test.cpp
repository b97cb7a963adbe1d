// The served bytes of the default island over real sockets: for a fixed list of requests
// covering every kind of resource (each tile format and scheme, the layers, vector, vegetation
// and Cesium tiles with and without extensions, the documents, 304s and the refusals of each
// route), the status, the headers a cache or client acts on and a hash of the body, against
// tests/data/golden/served_bytes.txt. STRAHLER_UPDATE_GOLDEN=1 rewrites the file.
//
// A guard for refactoring: a change to the server's code that is not meant to change what it
// serves must leave this file as it is. A change to the world (its generator) changes it
// whole; regenerate it then, in a commit of its own that says so.
#include "tile_server_harness.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace strahler::app {
namespace {

using test_support::HttpResponse;
using test_support::request;
using test_support::Running;

/// The headers CesiumJS sends for terrain (every extension it knows).
constexpr const char* kCesiumJs =
    "Accept: application/vnd.quantized-mesh;extensions=octvertexnormals-watermask-metadata,"
    "application/octet-stream;q=0.9,*/*;q=0.01\r\n";

/// One request of the list: a target with placeholders ({v}: the world's version; {c12} …:
/// the level's Cesium tile (TMS) holding the island's centre, "z/x/y"), and extra headers
/// ({etag}: the previous response's ETag).
struct Probe {
  std::string target;
  std::string headers;
  std::string label; ///< Names the headers in the golden file ("" when there are none).
};

std::vector<Probe> probes() {
  const std::string gzip = "Accept-Encoding: gzip\r\n";
  const std::string z12 = "/worlds/island/tiles/12/1736/1494";
  const std::string layers = "/worlds/island/layers/";
  const std::string cesium = "/worlds/island/cesium/";
  std::vector<Probe> p = {
      // Documents.
      {"/health", "", ""},
      {"/", "", ""},
      {"/worlds", "", ""},
      {"/worlds/island", "", ""},
      {"/worlds/island/tilejson.json", "", ""},
      {"/worlds/island/vector/tilejson.json", "", ""},
      {layers + "slope/tilejson.json", "", ""},
      {layers + "vegetation/tilejson.json?species=bush", "", ""},
      {layers + "hillshade/tilejson.json?azimuth=270&altitude=30", "", ""},
      {cesium + "layer.json", "", ""},
      {"/worlds/island/features.geojson", "", ""},
      {"/worlds/island/rivers.geojson", "", ""},
      {"/worlds/island/rivers.geojson?v={v}", gzip, "gzip"},
      {"/worlds/island/rivers.geojson?v={v}", gzip + "If-None-Match: {etag}\r\n",
       "gzip+if-none-match"},
      // Terrain, Web Mercator: every format, the size and the version.
      {z12 + ".png", "", ""},
      {z12 + ".png?v={v}", "", ""},
      {z12 + ".png?v={v}", "If-None-Match: {etag}\r\n", "if-none-match"},
      {z12 + ".png?encoding=terrarium", "", ""},
      {z12 + ".png?encoding=mapbox&size=512", "", ""},
      {z12 + ".png16", "", ""},
      {z12 + ".tif", "", ""},
      {z12 + ".exr?size=64", "", ""},
      {z12 + ".relief", "", ""},
      {z12 + ".drc?size=32", "", ""},
      {z12 + ".glb?size=32", "", ""},
      {"/worlds/island/tiles/9/216/186.png", "", ""},
      {"/worlds/island/tiles/3/1/2.png", "", ""},
      // Terrain, local scheme.
      {"/worlds/island/local/0/0/0.png", "", ""},
      {"/worlds/island/local/2/1/2.png16", "", ""},
      {"/worlds/island/local/2/1/2.relief", "", ""},
      {"/worlds/island/local/2/1/2.drc", "", ""},
      {"/worlds/island/local/2/1/2.glb?size=16", "", ""},
      // Layers, each one, their parameters, the local scheme.
      {layers + "slope/12/1736/1494.png", "", ""},
      {layers + "aspect/12/1736/1494.png", "", ""},
      {layers + "illumination/12/1736/1494.png", "", ""},
      {layers + "hillshade/12/1736/1494.png", "", ""},
      {layers + "hillshade/12/1736/1494.png?azimuth=270&altitude=30", "", ""},
      {layers + "humidity/12/1736/1494.png", "", ""},
      {layers + "sediment/12/1736/1494.png", "", ""},
      {layers + "vegetation/12/1736/1494.png", "", ""},
      {layers + "vegetation/12/1736/1494.png?species=bush", "", ""},
      {layers + "water/12/1736/1494.png?size=128", "", ""},
      {layers + "water/local/2/1/2.png?size=64", "", ""},
      // Vector tiles.
      {"/worlds/island/vector/12/1736/1494.mvt", "", ""},
      {"/worlds/island/vector/12/1736/1494.mvt", gzip, "gzip"},
      {"/worlds/island/vector/9/216/186.mvt?v={v}", "", ""},
      // Vegetation tiles: a forest, a shore (gzip), the sea, scrub at zoom 17.
      {"/worlds/island/vegetation/16/27784/23912.json", "", ""},
      {"/worlds/island/vegetation/16/27796/23873.json", gzip, "gzip"},
      {"/worlds/island/vegetation/16/27796/23872.json", "", ""},
      {"/worlds/island/vegetation/17/55566/47814.json", "", ""},
      // Cesium terrain: plain, CesiumJS's extensions, cesium-native's (query), gzip, the
      // availability at level 0 and at sea.
      {cesium + "{c0}.terrain", kCesiumJs, "cesiumjs"},
      {cesium + "{c12}.terrain", "", ""},
      {cesium + "{c12}.terrain", kCesiumJs, "cesiumjs"},
      {cesium + "{c12}.terrain?v={v}", kCesiumJs, "cesiumjs"},
      {cesium + "{c12}.terrain?v={v}", std::string(kCesiumJs) + "If-None-Match: {etag}\r\n",
       "cesiumjs+if-none-match"},
      {cesium + "{c12}.terrain?extensions=watermask", "", ""},
      {cesium + "{c11}.terrain", std::string(kCesiumJs) + gzip, "cesiumjs+gzip"},
      {cesium + "{c10}.terrain",
       "Accept: application/vnd.quantized-mesh;extensions=octvertexnormals\r\n",
       "octvertexnormals"},
      {cesium + "8/0/0.terrain", "", ""},
      // Refusals, route by route.
      {"/worlds/nope", "", ""},
      {"/worlds/nope/tiles/0/0/0.png", "", ""},
      {"/worlds/island/unknown.json", "", ""},
      {"/worlds/island/%zz", "", ""},
      {"/worlds/island/tiles/3/1/0.png/", "", ""},
      {"/missing.js", "", ""},
      {"/worlds/island/tiles/19/0/0.png", "", ""},
      {"/worlds/island/tiles/3/8/0.png", "", ""},
      {"/worlds/island/tiles/3/1/0.bmp", "", ""},
      {"/worlds/island/tiles/3/01/0.png", "", ""},
      {"/worlds/island/tiles/3/1/0.png?size=5000", "", ""},
      {"/worlds/island/tiles/3/1/0.tif?encoding=terrarium", "", ""},
      {"/worlds/island/tiles/3/1/0.png?bogus=1", "", ""},
      {"/worlds/island/tiles/0/0/0.terrain", "", ""},
      {"/worlds/island/tiles/0/0/0.mvt", "", ""},
      {"/worlds/island/local/40/0/0.png", "", ""},
      {"/worlds/island/local/1/1/0.glb?size=1024", "", ""},
      {layers + "snow/12/1736/1494.png", "", ""},
      {layers + "slope/12/1736/1494.jpg", "", ""},
      {layers + "slope/19/0/0.png", "", ""},
      {layers + "slope/12/1736/1494.png?size=8", "", ""},
      {layers + "slope/tiles/12/1736/1494.png", "", ""},
      {layers + "hillshade/12/1736/1494.png?azimuth=400", "", ""},
      {layers + "vegetation/12/1736/1494.png?species=oak", "", ""},
      {layers + "slope/tilejson.json?size=512", "", ""},
      {layers + "snow/tilejson.json", "", ""},
      {"/worlds/island/vector/19/0/0.mvt", "", ""},
      {"/worlds/island/vector/2/4/0.mvt", "", ""},
      {"/worlds/island/vector/0/0/x.mvt", "", ""},
      {"/worlds/island/vector/0/0/0.png", "", ""},
      {"/worlds/island/vector/0/0/0.mvt?size=512", "", ""},
      {"/worlds/island/vegetation/19/0/0.json", "", ""},
      {"/worlds/island/vegetation/16/65536/0.json", "", ""},
      {"/worlds/island/vegetation/16/0/00.json", "", ""},
      {"/worlds/island/vegetation/16/0/0.png", "", ""},
      {"/worlds/island/vegetation/10/0/0.json", "", ""},
      {"/worlds/island/vegetation/15/13892/11956.json", "", ""},
      {cesium + "18/0/0.terrain", "", ""},
      {cesium + "0/2/0.terrain", "", ""},
      {cesium + "1/0/2.terrain", "", ""},
      {cesium + "0/0/x.terrain", "", ""},
      {cesium + "0/0/0.png", "", ""},
      {cesium + "{c12}.terrain?extensions=bogus", "", ""},
      {cesium + "{c12}.terrain?size=5", "", ""},
      {cesium + "{c12}.terrain",
       "Accept: application/vnd.quantized-mesh;extensions=vertexnormals\r\n", "vertexnormals"},
  };
  return p;
}

/// 64-bit FNV-1a of `bytes`, in hex.
std::string fnv1a(const std::string& bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

void replaceAll(std::string& text, const std::string& what, const std::string& with) {
  for (std::size_t at = text.find(what); at != std::string::npos;
       at = text.find(what, at + with.size()))
    text.replace(at, what.size(), with);
}

/// The Cesium tile (TMS row) of level z holding `center` (lon, lat), as "z/x/y".
std::string cesiumTileOf(const nlohmann::json& center, int z) {
  const double side = 180.0 / static_cast<double>(std::int64_t{1} << z);
  const auto x = static_cast<std::int64_t>(std::floor((center[0].get<double>() + 180.0) / side));
  const auto y = static_cast<std::int64_t>(std::floor((center[1].get<double>() + 90.0) / side));
  return std::to_string(z) + "/" + std::to_string(x) + "/" + std::to_string(y);
}

std::string header(const HttpResponse& r, const std::string& name) {
  const auto h = r.headers.find(name);
  return h == r.headers.end() || h->second.empty() ? "-" : h->second;
}

/// One line of the golden file: what was asked, then what came back (tab-separated).
std::string describe(const Probe& probe, const HttpResponse& r) {
  std::ostringstream line;
  line << probe.target << (probe.label.empty() ? "" : " [" + probe.label + "]") << '\t' << r.status
       << '\t' << header(r, "etag") << '\t' << header(r, "content-type") << '\t'
       << header(r, "content-encoding") << '\t' << header(r, "cache-control") << '\t'
       << header(r, "vary") << '\t' << r.body.size() << '\t' << fnv1a(r.body);
  return line.str();
}

std::vector<std::string> linesOf(std::istream& in) {
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#')
      lines.push_back(line);
  return lines;
}

TEST(ServedBytes, EveryKindOfResourceIsServedAsRecorded) {
  Running s;
  const std::string version = test_support::servedVersion(s.port());
  ASSERT_FALSE(version.empty());
  const auto center = nlohmann::json::parse(request(s.port(), "/worlds/island").body)["center"];
  std::vector<std::string> served;
  std::string etag;
  for (const Probe& probe : probes()) {
    std::string target = probe.target, headers = probe.headers;
    replaceAll(target, "{v}", version);
    for (int z : {0, 10, 11, 12})
      replaceAll(target, "{c" + std::to_string(z) + "}", cesiumTileOf(center, z));
    replaceAll(headers, "{etag}", etag);
    HttpResponse r = request(s.port(), target, "GET", headers);
    ASSERT_NE(r.status, 0) << target << ": no answer";
    // TileJSONs name the server's origin, whose port is new on each run.
    replaceAll(r.body, "127.0.0.1:" + std::to_string(s.port()), "127.0.0.1:{port}");
    etag = header(r, "etag");
    served.push_back(describe(probe, r));
  }
  ASSERT_GE(served.size(), 40u);

  const std::filesystem::path path =
      std::filesystem::path(STRAHLER_TEST_DATA_DIR) / "golden" / "served_bytes.txt";
  if (const char* update = std::getenv("STRAHLER_UPDATE_GOLDEN");
      update != nullptr && std::string(update) == "1") {
    std::ofstream out(path);
    out << "# What the default island serves (tests/app/served_bytes_test.cpp); tab-separated:\n"
           "# request [headers], status, ETag, Content-Type, Content-Encoding, Cache-Control,\n"
           "# Vary, body bytes, FNV-1a 64 of the body (the server's port written {port}).\n"
           "# STRAHLER_UPDATE_GOLDEN=1 rewrites it.\n";
    for (const std::string& line : served)
      out << line << '\n';
    GTEST_SKIP() << "rewrote " << path;
  }
  std::ifstream in(path);
  ASSERT_TRUE(in) << path << " is missing: run with STRAHLER_UPDATE_GOLDEN=1";
  const std::vector<std::string> golden = linesOf(in);
  ASSERT_EQ(served.size(), golden.size())
      << "the list of requests changed: run with STRAHLER_UPDATE_GOLDEN=1";
  for (std::size_t i = 0; i < served.size(); ++i)
    EXPECT_EQ(served[i], golden[i]) << "served (first) differs from " << path << " (second)";
}

} // namespace
} // namespace strahler::app
