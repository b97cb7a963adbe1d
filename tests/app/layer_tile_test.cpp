// Layer tiles (layers/{name}/...png): canonical routes and their errors, the PNG each layer
// encodes (decoded with libspng), tiles that are cuts of one picture (so neighbours agree along
// their shared edges), the same bytes twice, and the tile pipeline's HTTP rules over real
// sockets (ETag, 304, CORS, TileJSON, 400/404 with their messages).
#include "layer_route.h"
#include "test_worlds.h"
#include "tile_server_harness.h"
#include "tile_service.h"

#include "strahler/construction/world_builder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <spng.h>
#include <string>
#include <vector>

namespace strahler::app {
namespace {

using test_support::HttpResponse;

construction::WorldData island() {
  return construction::generateWorldData(strahler::test_support::defaultIslandSpec(), "layers")
      .value();
}

const TileService& service() {
  static const TileService s(island());
  return s;
}

/// A z12 Web Mercator tile over the island's hills, rivers in it (as relief_tile_test's).
constexpr geometry::TileId kHills{12, 1736, 1494};

/// A decoded grey PNG: its samples (8- or 16-bit) and depth.
struct Grey {
  std::uint32_t width = 0, height = 0;
  int depth = 0;
  std::vector<std::uint16_t> samples;
};

Grey decode(const std::string& png) {
  Grey out;
  std::unique_ptr<spng_ctx, decltype(&spng_ctx_free)> ctx(spng_ctx_new(0), spng_ctx_free);
  spng_set_png_buffer(ctx.get(), png.data(), png.size());
  spng_ihdr ihdr{};
  if (spng_get_ihdr(ctx.get(), &ihdr) != 0 || ihdr.color_type != SPNG_COLOR_TYPE_GRAYSCALE)
    return out;
  std::size_t size = 0;
  spng_decoded_image_size(ctx.get(), SPNG_FMT_RAW, &size);
  std::vector<std::uint8_t> raw(size);
  if (spng_decode_image(ctx.get(), raw.data(), raw.size(), SPNG_FMT_RAW, 0) != 0)
    return out;
  out.width = ihdr.width;
  out.height = ihdr.height;
  out.depth = ihdr.bit_depth;
  if (out.depth == 16)
    for (std::size_t i = 0; i + 1 < raw.size(); i += 2) // big-endian as stored
      out.samples.push_back(static_cast<std::uint16_t>(raw[i] << 8 | raw[i + 1]));
  else
    out.samples.assign(raw.begin(), raw.end());
  return out;
}

TileRequest layerRequest(LayerName name, geometry::TileId tile, int size = 0) {
  TileRequest r;
  r.format = TileFormat::kLayerPng;
  r.tile = tile;
  r.options.size = size;
  r.options.layer.name = name;
  if (name == LayerName::kHillshade) {
    r.options.layer.azimuthDeg = kDefaultSunAzimuthDeg;
    r.options.layer.altitudeDeg = kDefaultSunAltitudeDeg;
  }
  return r;
}

Grey render(const TileRequest& r) {
  auto tile = service().render(r);
  EXPECT_TRUE(tile.ok()) << tile.error().message;
  if (!tile.ok())
    return {};
  EXPECT_EQ(tile.value().mimeType, "image/png");
  return decode(tile.value().bytes);
}

TEST(LayerRoute, EverySpellingOfATileIsOneCanonicalRequest) {
  const std::vector<std::string> web{"worlds", "w", "layers", "hillshade", "12", "3", "4.png"};
  const auto plain = parseLayerRoute("w", web, {});
  ASSERT_TRUE(plain.ok()) << plain.error().message;
  const auto spelled =
      parseLayerRoute("w", web, {{"azimuth", "315.0"}, {"altitude", "45"}, {"size", "256"}});
  ASSERT_TRUE(spelled.ok()) << spelled.error().message;
  EXPECT_EQ(tileKey(plain.value()), tileKey(spelled.value()));
  EXPECT_EQ(tileKey(plain.value()), "w|tiles|12|3|4|layer|0|hillshade|315|45");
  const auto west = parseLayerRoute("w", web, {{"azimuth", "270"}});
  EXPECT_NE(tileKey(west.value()), tileKey(plain.value()));
  EXPECT_EQ(layerQuery(west.value().options.layer), "?azimuth=270&altitude=45");
  const auto local =
      parseLayerRoute("w", {"worlds", "w", "layers", "vegetation", "local", "2", "1", "2.png"},
                      {{"species", "bush"}});
  ASSERT_TRUE(local.ok()) << local.error().message;
  EXPECT_EQ(local.value().scheme, tiling::SchemeKind::kLocal);
  EXPECT_EQ(tileKey(local.value()), "w|local|2|1|2|layer|0|vegetation|1");
  EXPECT_EQ(layerQuery(local.value().options.layer), "?species=bush");
}

TEST(LayerRoute, BadInputGetsADefiniteStatusAndMessage) {
  const auto parse = [](const std::string& name, const std::map<std::string, std::string>& q,
                        const std::string& last = "4.png") {
    return parseLayerRoute("w", {"worlds", "w", "layers", name, "12", "3", last}, q);
  };
  const auto unknown = parse("snow", {});
  EXPECT_EQ(unknown.error().code, base::ErrorCode::kNotFound);
  EXPECT_NE(unknown.error().message.find("slope, aspect"), std::string::npos);
  EXPECT_EQ(parse("vegetation", {{"species", "oak"}}).error().code, base::ErrorCode::kNotFound);
  const std::vector<std::pair<std::string, std::map<std::string, std::string>>> bad{
      {"slope", {{"azimuth", "90"}}},      {"water", {{"species", "tree"}}},
      {"hillshade", {{"azimuth", "360"}}}, {"hillshade", {{"altitude", "90.5"}}},
      {"hillshade", {{"azimuth", "-1"}}},  {"hillshade", {{"azimuth", "1e2"}}},
      {"hillshade", {{"azimuth", "nan"}}}, {"slope", {{"size", "8"}}},
      {"slope", {{"size", "2000"}}},       {"slope", {{"colour", "red"}}}};
  for (const auto& [name, query] : bad) {
    const auto r = parse(name, query);
    ASSERT_FALSE(r.ok()) << name;
    EXPECT_EQ(r.error().code, base::ErrorCode::kInvalidInput) << name << " " << r.error().message;
  }
  EXPECT_NE(parse("slope", {{"azimuth", "90"}}).error().message.find("hillshade layer only"),
            std::string::npos);
  EXPECT_FALSE(parse("slope", {}, "4.jpg").ok());
  EXPECT_FALSE(parse("slope", {}, "04.png").ok());
}

/// Pixels of a water tile (0 or 255: asserted) by the height of the same tile's 16-bit
/// heightmap at them: below −5 m (sea floor), above 5 m (land), and how many of each are wet.
struct WaterCount {
  int sea = 0, seaWet = 0, land = 0, landWet = 0;
};

WaterCount countWater(const geometry::TileId& tile) {
  const Grey water = render(layerRequest(LayerName::kWater, tile));
  TileRequest png16;
  png16.format = TileFormat::kPng16;
  png16.tile = tile;
  const Grey heights = render(png16);
  WaterCount n;
  EXPECT_GT(water.width, 1u);
  EXPECT_GT(heights.width, 1u);
  // The heightmap's sample nearest a pixel (the two grids need not be the same size).
  const auto near = [](std::uint32_t i, std::uint32_t from, std::uint32_t to) {
    return static_cast<std::uint32_t>((i + 0.5) * to / from);
  };
  for (std::uint32_t y = 0; y < water.height; ++y)
    for (std::uint32_t x = 0; x < water.width; ++x) {
      const std::uint16_t s = water.samples[y * water.width + x];
      EXPECT_TRUE(s == 0 || s == 255) << s;
      const double h = heights.samples[near(y, water.height, heights.height) * heights.width +
                                       near(x, water.width, heights.width)] /
                           10.0 -
                       1000.0;
      if (h < -5.0) {
        ++n.sea;
        n.seaWet += s == 255;
      } else if (h > 5.0) {
        ++n.land;
        n.landWet += s == 255;
      }
    }
  std::printf("water tile %d/%d/%d: sea %d (wet %d), land %d (wet %d)\n", tile.z,
              static_cast<int>(tile.x), static_cast<int>(tile.y), n.sea, n.seaWet, n.land,
              n.landWet);
  return n;
}

TEST(LayerTile, EachLayerHasItsDocumentedEncoding) {
  for (std::size_t i = 0; i < std::size(kLayerNames); ++i) {
    const auto name = static_cast<LayerName>(i);
    const Grey g = render(layerRequest(name, kHills, 64));
    EXPECT_EQ(g.width, 64u) << kLayerNames[i];
    EXPECT_EQ(g.samples.size(), 64u * 64u) << kLayerNames[i];
    const bool wide = name == LayerName::kSlope || name == LayerName::kAspect;
    EXPECT_EQ(g.depth, wide ? 16 : 8) << kLayerNames[i];
  }
  // Slope in hundredths of a degree: hills, never past 90°.
  const Grey slope = render(layerRequest(LayerName::kSlope, kHills));
  const auto [lo, hi] = std::minmax_element(slope.samples.begin(), slope.samples.end());
  EXPECT_LE(*hi, 9000);
  EXPECT_GT(*hi, 500); // steeper than 5° somewhere in the hills
  EXPECT_LT(*lo, *hi);
  // Aspect in hundredths of a degree below 360°, or 65535 on flat ground.
  for (std::uint16_t a : render(layerRequest(LayerName::kAspect, kHills)).samples)
    ASSERT_TRUE(a < 36000 || a == 65535) << a;
  // Sediment in centimetres, at most Sediment::kMaxM.
  for (std::uint16_t s : render(layerRequest(LayerName::kSediment, kHills)).samples)
    ASSERT_LE(s, 200);
  // Water: 0 or 255; wet where the same tile's 16-bit heightmap (height = v / 10 − 1000 m, a
  // renderer of its own) is sea floor, and along the rivers on land; dry on most land. Two
  // z14 tiles (rivers show where they are at least a pixel, 9 m, wide): one at a river mouth,
  // one inland.
  const WaterCount mouth = countWater({14, 6952, 5969});
  EXPECT_GT(mouth.sea, 1000) << "the tile holds sea";
  EXPECT_GE(mouth.seaWet, 0.98 * mouth.sea) << "the sea is water (up to the shore's pixels)";
  EXPECT_GT(mouth.land, 1000) << "the tile holds land";
  EXPECT_GT(mouth.landWet, 20) << "the river's mouth is water on the land";
  EXPECT_LT(mouth.landWet, mouth.land / 4) << "most of the land is dry";
  const WaterCount inland = countWater({14, 6949, 5969});
  EXPECT_EQ(inland.sea, 0) << "an inland tile";
  EXPECT_GT(inland.landWet, 200) << "rivers show as water on the land";
  EXPECT_LT(inland.landWet, inland.land / 4) << "most of the land is dry";
}

TEST(LayerTile, TilesAreCutsOfTheirParentSoNeighboursAgreeAlongTheirEdges) {
  // A parent tile of 2n pixels samples exactly the points of its four children of n pixels:
  // each child is the parent's quarter, so the children agree with each other along every
  // shared edge (the sky view's rays and the slopes reach across it).
  const geometry::TileId parent{kHills.z - 1, kHills.x / 2, kHills.y / 2};
  const int n = 128;
  for (const LayerName name : {LayerName::kSlope, LayerName::kIllumination, LayerName::kHumidity,
                               LayerName::kVegetation, LayerName::kWater, LayerName::kAspect}) {
    const Grey whole = render(layerRequest(name, parent, 2 * n));
    ASSERT_EQ(whole.samples.size(), static_cast<std::size_t>(4 * n * n));
    for (int q = 0; q < 4; ++q) {
      const geometry::TileId child{kHills.z, parent.x * 2 + q % 2, parent.y * 2 + q / 2};
      const Grey part = render(layerRequest(name, child, n));
      ASSERT_EQ(part.samples.size(), static_cast<std::size_t>(n * n));
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          ASSERT_EQ(
              part.samples[static_cast<std::size_t>(y * n + x)],
              whole.samples[static_cast<std::size_t>((y + q / 2 * n) * 2 * n + x + q % 2 * n)])
              << kLayerNames[static_cast<std::size_t>(name)] << " child " << q << " at " << x << ","
              << y;
    }
  }
}

TEST(LayerTile, VegetationFollowsTheCurvesOfTheWorldsParams) {
  // Trees that need 9,000 m of soil: none anywhere; bushes keep their default curves.
  input::WorldSpec spec = strahler::test_support::defaultIslandSpec();
  spec.params.vegetation["tree"] = {{9000, 9001, 9002, 9003}, {0, 0, 1, 1}, {0, 0, 1, 1}};
  const TileService barren(construction::generateWorldData(spec, "barren").value());
  TileRequest trees = layerRequest(LayerName::kVegetation, kHills, 64);
  const auto none = barren.render(trees);
  ASSERT_TRUE(none.ok()) << none.error().message;
  for (std::uint16_t d : decode(none.value().bytes).samples)
    ASSERT_EQ(d, 0);
  EXPECT_GT(render(trees).samples, decode(none.value().bytes).samples); // the default world's
  TileRequest bushes = trees;
  bushes.options.layer.species = 1;
  EXPECT_EQ(decode(barren.render(bushes).value().bytes).samples, render(bushes).samples);
}

TEST(LayerTile, TheSameRequestGivesTheSameBytes) {
  const TileRequest r = layerRequest(LayerName::kVegetation, kHills);
  const auto a = service().render(r), b = service().render(r);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a.value().bytes, b.value().bytes);
  // The geographic pyramid has no layer tiles.
  TileRequest cesium = r;
  cesium.scheme = tiling::SchemeKind::kGeographic;
  EXPECT_EQ(service().checkTile(cesium).error().code, base::ErrorCode::kInvalidInput);
}

HttpResponse get(std::uint16_t port, const std::string& target, const std::string& extra = "") {
  return test_support::request(port, target, "GET", extra);
}

TEST(LayerTile, IsServedLikeEveryOtherTile) {
  test_support::Running s; // the default island as "island", two workers
  const std::uint16_t port = s.port();
  const std::string path = "/worlds/island/layers/slope/12/1736/1494.png";
  HttpResponse tile = get(port, test_support::versioned(port, path));
  ASSERT_EQ(tile.status, 200) << tile.body;
  EXPECT_EQ(tile.headers["content-type"], "image/png");
  EXPECT_EQ(tile.headers["access-control-allow-origin"], "*");
  EXPECT_EQ(tile.headers["cache-control"], "public, max-age=86400, immutable");
  const std::string etag = tile.headers["etag"];
  ASSERT_FALSE(etag.empty());
  EXPECT_EQ(decode(tile.body).depth, 16);
  EXPECT_EQ(get(port, path, "If-None-Match: " + etag + "\r\n").status, 304);
  EXPECT_EQ(get(port, path + "?size=256").headers["etag"], etag);
  // Another layer of the same tile is another tile.
  HttpResponse shade = get(port, "/worlds/island/layers/hillshade/12/1736/1494.png");
  EXPECT_EQ(shade.status, 200);
  EXPECT_NE(shade.headers["etag"], etag);
  HttpResponse west =
      get(port, "/worlds/island/layers/hillshade/12/1736/1494.png?azimuth=270&altitude=30");
  EXPECT_EQ(west.status, 200);
  EXPECT_NE(west.headers["etag"], shade.headers["etag"]);
  EXPECT_EQ(get(port, "/worlds/island/layers/water/local/2/1/2.png?size=64").status, 200);
  // TileJSON per layer, with the layer's parameters in its tile URLs.
  HttpResponse tj = get(port, "/worlds/island/layers/vegetation/tilejson.json?species=bush");
  ASSERT_EQ(tj.status, 200) << tj.body;
  const auto doc = nlohmann::json::parse(tj.body);
  const std::string url = doc["tiles"][0];
  EXPECT_NE(url.find("/worlds/island/layers/vegetation/{z}/{x}/{y}.png?species=bush"),
            std::string::npos)
      << url;
  EXPECT_NE(doc["description"].get<std::string>().find("8-bit grey"), std::string::npos);
  // Bad input: unknown layers and species 404, bad parameters 400, zooms past the pyramid 404.
  HttpResponse unknown = get(port, "/worlds/island/layers/snow/12/1736/1494.png");
  EXPECT_EQ(unknown.status, 404);
  EXPECT_NE(unknown.body.find("unknown layer 'snow'"), std::string::npos) << unknown.body;
  const auto refused = [&](const std::string& target, int status, const std::string& message) {
    test_support::expectRefused(port, target, status, message);
  };
  refused("/worlds/island/layers/snow/tilejson.json", 404, "unknown layer 'snow'");
  refused("/worlds/island/layers/vegetation/12/1736/1494.png?species=oak", 404,
          "unknown species 'oak'");
  refused(path + "?azimuth=90", 400, "hillshade layer only");
  refused("/worlds/island/layers/hillshade/12/1736/1494.png?azimuth=400", 400,
          "azimuth must be in [0, 360) degrees");
  refused("/worlds/island/layers/hillshade/12/1736/1494.png?altitude=-5", 400,
          "altitude must be a plain decimal number");
  refused("/worlds/island/layers/slope/12/1736/1494.png?size=8", 400, "size must be in [16, 1024]");
  refused("/worlds/island/layers/slope/12/1736/1494.jpg", 400, "a layer tile is named {y}.png");
  refused("/worlds/island/layers/slope/tiles/12/1736/1494.png", 400,
          "layer tiles are layers/{name}/{z}/{x}/{y}.png");
  refused("/worlds/island/layers/slope/tilejson.json?size=512", 400, "not size");
  HttpResponse deep = get(port, "/worlds/island/layers/slope/19/0/0.png");
  EXPECT_EQ(deep.status, 404);
  EXPECT_NE(deep.body.find("zoom 0..18"), std::string::npos) << deep.body;
  s.server.stop();
}

} // namespace
} // namespace strahler::app
