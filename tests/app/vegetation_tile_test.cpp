// Vegetation tiles (vegetation/{z}/{x}/{y}.json): the route and its key, a density that is a
// pure function of the point whichever tile asks, and over real sockets the JSON, the tile
// pipeline's headers (gzip, ETag, 304, CORS), no plant on water, children that hold exactly
// their parent's trees, and the refusals.
#include "gzip.h"
#include "lattice_density.h"
#include "result_matchers.h"
#include "router.h"
#include "test_worlds.h"
#include "tile_request.h"
#include "tile_server_harness.h"
#include "web_tile_route.h"

#include "strahler/construction/world_builder.h"
#include "strahler/tiling/tile_evaluator.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <memory>
#include <spng.h>
#include <string>
#include <vector>

namespace strahler::app {
namespace {

using test_support::HttpResponse;
using test_support::request;
using test_support::Running;

/// A z16 tile in the island's hills (under layer_tile_test's z12 kHills), trees on it.
constexpr geometry::TileId kForest{16, 27784, 23912};
/// A z16 tile with trees and bushes under it (at zoom 17).
constexpr geometry::TileId kScrub{16, 27783, 23907};
/// A z16 tile on the island's coast: land and sea.
constexpr geometry::TileId kShore{16, 27796, 23873};
/// A z16 tile at sea, north of kShore.
constexpr geometry::TileId kSea{16, 27796, 23872};

std::string path(const geometry::TileId& t) {
  return "/worlds/island/vegetation/" + std::to_string(t.z) + "/" + std::to_string(t.x) + "/" +
         std::to_string(t.y) + ".json";
}

/// The samples of an 8-bit grey PNG (libspng), empty if it is not one.
std::vector<std::uint8_t> greyPixels(const std::string& png) {
  std::unique_ptr<spng_ctx, decltype(&spng_ctx_free)> ctx(spng_ctx_new(0), spng_ctx_free);
  spng_set_png_buffer(ctx.get(), png.data(), png.size());
  spng_ihdr ihdr{};
  if (spng_get_ihdr(ctx.get(), &ihdr) != 0 || ihdr.color_type != SPNG_COLOR_TYPE_GRAYSCALE ||
      ihdr.bit_depth != 8)
    return {};
  std::size_t size = 0;
  spng_decoded_image_size(ctx.get(), SPNG_FMT_RAW, &size);
  std::vector<std::uint8_t> raw(size);
  if (spng_decode_image(ctx.get(), raw.data(), raw.size(), SPNG_FMT_RAW, 0) != 0)
    return {};
  return raw;
}

nlohmann::json fetch(const Running& s, const geometry::TileId& t) {
  const HttpResponse r = request(s.port(), path(t));
  EXPECT_EQ(r.status, 200) << path(t) << " " << r.body;
  return r.status == 200 ? nlohmann::json::parse(r.body) : nlohmann::json::object();
}

/// The island with what a vegetation tile reads: evaluator, Web Mercator scheme, water.
struct Island {
  construction::World world{
      construction::generateWorldData(strahler::test_support::defaultIslandSpec(), "k").value()};
  geometry::LocalProjection projection{world.data().projectionCenter.x,
                                       world.data().projectionCenter.y};
  tiling::TileEvaluator evaluator{world};
  tiling::TileScheme web = tiling::TileScheme::webMercator(projection);
  tiling::WaterMask water{world, projection};

  LatticeDensity density(const geometry::TileId& t) {
    RenderedTile cost;
    return LatticeDensity(RenderContext{evaluator, web}, world, water, {t.z, t.x, t.y}, cost);
  }
};

TEST(VegetationRoute, TheRouterAndTheParserNameTheTileAndItsCoding) {
  EXPECT_EQ(routeOf({"worlds", "w", "vegetation", "16", "2", "3.json"}).endpoint,
            Endpoint::kVegetationTile);
  EXPECT_EQ(routeOf({"worlds", "w", "vegetation", "16", "3.json"}).endpoint,
            Endpoint::kNoSuchResource);
  const std::vector<std::string> s = {"worlds", "w", "vegetation", "16", "27784", "23912.json"};
  STRAHLER_ASSIGN_OR_ASSERT(const TileRequest plain, parseVegetationRoute("w", s, {}, ""));
  STRAHLER_ASSIGN_OR_ASSERT(const TileRequest zipped, parseVegetationRoute("w", s, {}, "gzip"));
  EXPECT_EQ(plain.kind(), TileKind::kVegetation);
  EXPECT_EQ(plain.scheme, tiling::SchemeKind::kWebMercator);
  EXPECT_EQ(plain.tile, kForest);
  EXPECT_FALSE(plain.options.gzip);
  EXPECT_TRUE(zipped.options.gzip);
  EXPECT_EQ(tileKey(plain), "w|tiles|16|27784|23912|json|0|id");
  EXPECT_EQ(tileKey(zipped), "w|tiles|16|27784|23912|json|0|gz");
  EXPECT_FALSE(parseVegetationRoute("w", s, {{"species", "tree"}}, "").ok());
}

TEST(LatticeDensity, APointHasTheSameDensityWhicheverTileAsks) {
  Island island;
  const geometry::TileId east{16, kForest.x + 1, kForest.y};
  const geometry::TileId child{17, 2 * kForest.x + 1, 2 * kForest.y + 1};
  const LatticeDensity a = island.density(kForest);
  const LatticeDensity b = island.density(east);
  const LatticeDensity c = island.density(child);
  EXPECT_GT(a.side(), LatticeDensity::kLatticeSize);
  // Points along the shared edge of kForest and its east neighbour, inside the child (its
  // south-east quarter): every field covers them.
  const vegetation::Footprint f =
      vegetation::webTileFootprint(island.projection, {child.z, child.x, child.y});
  std::vector<geometry::Vec2> points;
  for (int i = 0; i < 400; ++i)
    points.push_back({f.bounds.max.x - 5.0 + 0.0371 * i, f.bounds.min.y + 0.517 * i});
  double sum = 0.0;
  for (std::size_t s = 0; s < vegetation::kSpecies.size(); ++s) {
    std::vector<float> da(points.size()), db(points.size()), dc(points.size());
    a.sample(s, points, da);
    b.sample(s, points, db);
    c.sample(s, points, dc);
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_EQ(da[i], db[i]) << "species " << s << " point " << i;
      ASSERT_EQ(da[i], dc[i]) << "species " << s << " point " << i;
      ASSERT_GE(da[i], 0.0f);
      ASSERT_LE(da[i], 1.0f);
      sum += da[i];
    }
    for (std::size_t i = 0; i < points.size(); i += 37)
      ASSERT_EQ(a.heightAt(points[i]), b.heightAt(points[i]));
  }
  EXPECT_GT(sum, 0.0); // something grows there: the test compares densities, not zeros
}

TEST(VegetationServer, ATileIsJsonWithTheTilePipelinesHeaders) {
  Running s;
  HttpResponse r = request(s.port(), path(kForest));
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.headers["content-type"], "application/json");
  EXPECT_EQ(r.headers["access-control-allow-origin"], "*");
  EXPECT_EQ(r.headers["vary"], "Accept-Encoding");
  EXPECT_EQ(r.headers.count("content-encoding"), 0u);
  ASSERT_FALSE(r.headers["etag"].empty());
  const auto json = nlohmann::json::parse(r.body);
  EXPECT_EQ(json["tile"], nlohmann::json::array({kForest.z, kForest.x, kForest.y}));
  ASSERT_EQ(json["species"].size(), vegetation::kSpecies.size());
  EXPECT_EQ(json["species"][0]["name"], "tree");
  ASSERT_GT(json["instances"].size(), 100u);
  for (const auto& i : json["instances"]) {
    EXPECT_EQ(i["species"], 0); // zoom 16: trees only
    const double x = i["x"], y = i["y"];
    EXPECT_TRUE(x >= 0.0 && x < 1.0 && y >= 0.0 && y < 1.0) << i.dump();
    EXPECT_GE(i["radius"].get<double>(), vegetation::kSpecies[0].startRadius);
    EXPECT_GT(i["h"].get<double>(), 0.0) << i.dump(); // on land
    ASSERT_TRUE(i["e"].is_number() && i["n"].is_number()) << i.dump();
  }
  EXPECT_EQ(request(s.port(), path(kForest), "GET", "If-None-Match: " + r.headers["etag"] + "\r\n")
                .status,
            304);
  HttpResponse zipped = request(s.port(), path(kForest), "GET", "Accept-Encoding: gzip\r\n");
  ASSERT_EQ(zipped.status, 200);
  EXPECT_EQ(zipped.headers["content-encoding"], "gzip");
  EXPECT_NE(zipped.headers["etag"], r.headers["etag"]);
  const auto unzipped = gzip::decompress(zipped.body, 64u << 20);
  ASSERT_TRUE(unzipped.ok());
  EXPECT_TRUE(unzipped.value() == r.body);
}

TEST(VegetationServer, NoPlantStandsOnWater) {
  Running s;
  const nlohmann::json json = fetch(s, kShore);
  // The zoom-16 water layer tile of 256 pixels is the density's lattice: every plant's lattice
  // cell is land at its four corners.
  const HttpResponse water =
      request(s.port(), "/worlds/island/layers/water/16/" + std::to_string(kShore.x) + "/" +
                            std::to_string(kShore.y) + ".png");
  ASSERT_EQ(water.status, 200);
  const std::vector<std::uint8_t> pixels = greyPixels(water.body);
  constexpr int n = LatticeDensity::kLatticeSize;
  ASSERT_EQ(pixels.size(), static_cast<std::size_t>(n * n));
  std::size_t wet = 0;
  for (std::uint8_t p : pixels)
    wet += p != 0;
  ASSERT_GT(wet, 1000u);         // the tile has sea
  ASSERT_LT(wet, pixels.size()); // and land
  ASSERT_GT(json["instances"].size(), 10u);
  std::size_t checked = 0;
  for (const auto& i : json["instances"]) {
    // Pixel centres at k + 0.5: the lattice cell's north-west corner.
    const int x0 = static_cast<int>(std::floor(i["x"].get<double>() * n - 0.5));
    const int y0 = static_cast<int>(std::floor(i["y"].get<double>() * n - 0.5));
    if (x0 < 0 || y0 < 0 || x0 + 1 >= n || y0 + 1 >= n)
      continue; // a corner in the neighbouring tile
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx)
        ASSERT_EQ(pixels[static_cast<std::size_t>((y0 + dy) * n + x0 + dx)], 0) << i.dump();
    ++checked;
  }
  EXPECT_GT(checked, 10u);
  EXPECT_TRUE(fetch(s, kSea)["instances"].empty());
}

TEST(VegetationServer, FourChildrenHoldExactlyTheirParentsTrees) {
  Running s;
  std::map<std::string, std::string> parent; // id → lon,lat
  const nlohmann::json whole = fetch(s, kScrub);
  for (const auto& i : whole["instances"])
    parent[i["id"]] = i["lon"].dump() + "," + i["lat"].dump() + "," + i["h"].dump();
  std::map<std::string, std::string> children;
  std::size_t bushes = 0;
  for (int q = 0; q < 4; ++q) {
    const nlohmann::json child = fetch(s, {17, 2 * kScrub.x + q % 2, 2 * kScrub.y + q / 2});
    for (const auto& i : child["instances"]) {
      if (i["species"] != 0) {
        ++bushes;
        continue;
      }
      EXPECT_TRUE(
          children.emplace(i["id"], i["lon"].dump() + "," + i["lat"].dump() + "," + i["h"].dump())
              .second)
          << "a tree in two children: " << i.dump();
    }
  }
  EXPECT_GT(parent.size(), 100u);
  EXPECT_EQ(children, parent);
  EXPECT_GT(bushes, 100u); // zoom 17 adds the bushes
}

TEST(VegetationServer, BadRequestsGetDefiniteAnswers) {
  Running s;
  const auto refused = [&](const std::string& path, int status, const std::string& message) {
    test_support::expectRefused(s.port(), path, status, message);
  };
  refused("/worlds/island/vegetation/15/13892/11956.json", 404, "zooms 16 to 18");
  refused("/worlds/island/vegetation/19/0/0.json", 404, "tile 19/0/0 is outside the grid");
  refused("/worlds/island/vegetation/16/65536/0.json", 404, "tile 16/65536/0 is outside the grid");
  refused("/worlds/island/vegetation/16/0/x.json", 400, "'x' is not a non-negative integer");
  refused("/worlds/island/vegetation/16/0/00.json", 400, "'00' has a leading zero");
  refused("/worlds/island/vegetation/16/0/0.png", 400, "a vegetation tile is named {y}.json");
  refused("/worlds/island/vegetation/16/0/0.json?size=512", 400, "unknown query parameter 'size'");
  refused("/worlds/island/tiles/16/0/0.json", 400, "vegetation tiles are served under");
  refused("/worlds/nowhere/vegetation/16/0/0.json", 404, "unknown world 'nowhere'");
}

} // namespace
} // namespace strahler::app
