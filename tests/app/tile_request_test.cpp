// A tile request's one canonical form: every spelling of a tile, parsed by the tile route,
// gives the key the server used before TileRequest existed (its cache key and ETag input).
#include "route_parser.h"
#include "tile_request.h"
#include "tile_route.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace strahler::app {
namespace {

/// The key of `target` as the server derives it: parseTarget, then parseTileRoute.
std::string keyOf(const std::string& target) {
  const auto parsed = parseTarget(target);
  EXPECT_TRUE(parsed.ok()) << target;
  if (!parsed.ok())
    return {};
  const auto& s = parsed.value().segments;
  const auto request = parseTileRoute(s[1], s, parsed.value().query);
  EXPECT_TRUE(request.ok()) << target << ": " << (request.ok() ? "" : request.error().message);
  return request.ok() ? tileKey(request.value()) : std::string();
}

TEST(TileRequest, EverySpellingTheRouteTestsUseHasTheOldKey) {
  const std::string web = "/worlds/island/tiles/10/433/373";
  const std::string local = "/worlds/island/local/2/1/2";
  // The groups of tile_server_test's EverySpellingOfATileHasOneCacheEntryAndOneEtag, each
  // with the key "world|scheme|z|x|y|format|size" the route parser built before.
  const std::vector<std::pair<std::vector<std::string>, std::string>> groups = {
      {{web + ".png", web + ".png?size=256", web + ".png?encoding=mapbox",
        web + ".png?size=256&encoding=mapbox", web + ".png?encoding=mapbox&size=256", web + ".png?",
        web + ".png?&", "/worlds/island/tiles/%31%30/433/373.png"},
       "island|tiles|10|433|373|png|0"},
      {{web + ".terrarium", web + ".png?encoding=terrarium", web + ".terrarium?size=256"},
       "island|tiles|10|433|373|terrarium|0"},
      {{web + ".tif", web + ".tiff", web + ".tiff?size=256"}, "island|tiles|10|433|373|tif|0"},
      {{local + ".glb", local + ".glb?size=64"}, "island|local|2|1|2|glb|0"},
      {{web + ".png?size=512"}, "island|tiles|10|433|373|png|512"},
      {{local + ".drc?size=32"}, "island|local|2|1|2|drc|32"},
      {{"/worlds/w/tiles/0/0/0.exr", "/worlds/w/tiles/0/0/0.exr?size=256"}, "w|tiles|0|0|0|exr|0"},
      {{"/worlds/w/tiles/30/1073741823/0.png16"}, "w|tiles|30|1073741823|0|png16|0"}};
  for (const auto& [spellings, key] : groups)
    for (const std::string& spelling : spellings)
      EXPECT_EQ(keyOf(spelling), key) << spelling;
}

TEST(TileRequest, TheRouteFillsEveryFieldOfTheRequest) {
  const auto parsed = parseTarget("/worlds/island/local/2/1/3.glb?size=128");
  ASSERT_TRUE(parsed.ok());
  const auto& s = parsed.value().segments;
  const auto request = parseTileRoute(s[1], s, parsed.value().query);
  ASSERT_TRUE(request.ok());
  EXPECT_EQ(request.value().world, "island");
  EXPECT_EQ(request.value().scheme, tiling::SchemeKind::kLocal);
  EXPECT_EQ(request.value().tile, (geometry::TileId{2, 1, 3}));
  EXPECT_EQ(request.value().format, TileFormat::kGlb);
  EXPECT_EQ(request.value().kind(), TileKind::kMesh);
  EXPECT_EQ(request.value().options.size, 128);
}

TEST(TileRequest, KeysOfDifferentTilesDiffer) {
  TileRequest a;
  a.world = "w";
  a.tile = {3, 4, 2};
  TileRequest b = a;
  EXPECT_EQ(tileKey(a), tileKey(b));
  for (auto change : {+[](TileRequest& r) { r.world = "v"; },
                      +[](TileRequest& r) { r.scheme = tiling::SchemeKind::kLocal; },
                      +[](TileRequest& r) { r.tile.z = 4; }, +[](TileRequest& r) { r.tile.x = 5; },
                      +[](TileRequest& r) { r.tile.y = 3; },
                      +[](TileRequest& r) { r.format = TileFormat::kTerrarium; },
                      +[](TileRequest& r) { r.options.size = 512; }}) {
    b = a;
    change(b);
    EXPECT_NE(tileKey(a), tileKey(b)) << tileKey(b);
  }
}

TEST(TileFormat, EachFormatHasItsKindAndTheKindItsSizes) {
  for (TileFormat f : {TileFormat::kTerrainRgb, TileFormat::kTerrarium, TileFormat::kPng16,
                       TileFormat::kTiff, TileFormat::kExr}) {
    EXPECT_EQ(tileKind(f), TileKind::kHeightmap) << canonicalFormatName(f);
    EXPECT_FALSE(isMeshFormat(f));
  }
  for (TileFormat f : {TileFormat::kDraco, TileFormat::kGlb}) {
    EXPECT_EQ(tileKind(f), TileKind::kMesh) << canonicalFormatName(f);
    EXPECT_TRUE(isMeshFormat(f));
  }
  const TileSizeRange raster = tileSizeRange(TileKind::kHeightmap);
  EXPECT_EQ(raster.min, TileSizes::kRasterMin);
  EXPECT_EQ(raster.max, TileSizes::kRasterMax);
  EXPECT_EQ(raster.defaultSize, TileSizes::kRasterDefault);
  const TileSizeRange mesh = tileSizeRange(TileKind::kMesh);
  EXPECT_EQ(mesh.min, TileSizes::kMeshMin);
  EXPECT_EQ(mesh.max, TileSizes::kMeshMax);
  EXPECT_EQ(mesh.defaultSize, TileSizes::kMeshDefault);
}

TEST(TileFormat, ReliefIsARasterPictureOfItsOwnKind) {
  ASSERT_TRUE(parseTileFormat("relief").ok());
  EXPECT_EQ(parseTileFormat("relief").value(), TileFormat::kRelief);
  EXPECT_STREQ(canonicalFormatName(TileFormat::kRelief), "relief");
  EXPECT_EQ(tileKind(TileFormat::kRelief), TileKind::kRelief);
  EXPECT_FALSE(isMeshFormat(TileFormat::kRelief));
  const TileSizeRange range = tileSizeRange(TileKind::kRelief);
  EXPECT_EQ(range.min, TileSizes::kRasterMin);
  EXPECT_EQ(range.max, TileSizes::kRasterMax);
  EXPECT_EQ(range.defaultSize, TileSizes::kRasterDefault);
  // One spelling per tile, the default size written or not; local tiles too.
  const std::string web = "/worlds/island/tiles/12/1736/1494";
  EXPECT_EQ(keyOf(web + ".relief"), "island|tiles|12|1736|1494|relief|0");
  EXPECT_EQ(keyOf(web + ".relief?size=256"), "island|tiles|12|1736|1494|relief|0");
  EXPECT_EQ(keyOf(web + ".relief?size=512"), "island|tiles|12|1736|1494|relief|512");
  EXPECT_EQ(keyOf("/worlds/island/local/2/1/2.relief"), "island|local|2|1|2|relief|0");
  // encoding= belongs to png tiles; sizes are the rasters'.
  for (const char* bad : {".relief?encoding=terrarium", ".relief?size=8", ".relief?size=2048"}) {
    const auto parsed = parseTarget(web + bad);
    ASSERT_TRUE(parsed.ok()) << bad;
    const auto& s = parsed.value().segments;
    EXPECT_FALSE(parseTileRoute(s[1], s, parsed.value().query).ok()) << bad;
  }
}

} // namespace
} // namespace strahler::app
