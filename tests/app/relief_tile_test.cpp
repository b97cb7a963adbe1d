// Colour-relief tiles (.relief): the heightmap tiles' samples, seamless hillshade across tile
// edges, and the tile pipeline's HTTP rules (ETag, 304, CORS, sizes) over real sockets.
#include "test_worlds.h"
#include "tile_server_harness.h"
#include "tile_service.h"

#include "strahler/construction/world_builder.h"
#include "strahler/encoding/rgb_png.h"
#include "strahler/render/shaded_relief.h"
#include "strahler/tiling/tile_evaluator.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace strahler::app {
namespace {

using test_support::HttpResponse;

construction::WorldData island() {
  return construction::generateWorldData(strahler::test_support::defaultIslandSpec(), "relief")
      .value();
}

/// A z12 Web Mercator tile over the island's hills (its east neighbour is hilly too).
constexpr geometry::TileId kHills{12, 1736, 1494};

/// Width, height, bit depth and colour type from a PNG's IHDR, read by hand (0s if not a PNG).
struct PngHeader {
  std::uint32_t width = 0, height = 0;
  int depth = 0, colourType = 0;
};

PngHeader pngHeader(const std::string& bytes) {
  if (bytes.size() < 33 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 ||
      bytes.compare(12, 4, "IHDR") != 0)
    return {};
  auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k)
      v = v << 8 | static_cast<std::uint8_t>(bytes[at + k]);
    return v;
  };
  return {u32(16), u32(20), static_cast<std::uint8_t>(bytes[24]),
          static_cast<std::uint8_t>(bytes[25])};
}

TEST(ReliefTile, SamplesTheHeightmapTilesPoints) {
  const TileService service(island());
  const tiling::TileEvaluator evaluator(service.world());
  for (const auto kind : {tiling::SchemeKind::kWebMercator, tiling::SchemeKind::kLocal}) {
    const tiling::TileScheme& scheme = service.scheme(kind);
    const geometry::TileId tile =
        kind == tiling::SchemeKind::kLocal ? geometry::TileId{2, 1, 2} : kHills;
    const int n = 64, w = n + 2;
    const std::vector<double> bordered = evaluator.evaluate(scheme.borderedRasterGrid(tile, n));
    const std::vector<double> raster = evaluator.evaluate(scheme.rasterGrid(tile, n));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        ASSERT_EQ(bordered[static_cast<std::size_t>((j + 1) * w + i + 1)],
                  raster[static_cast<std::size_t>(j * n + i)])
            << i << "," << j;
    const auto tileBytes = service.render({kind, tile, TileFormat::kRelief, {n}, {}});
    ASSERT_TRUE(tileBytes.ok()) << tileBytes.error().message;
    EXPECT_EQ(tileBytes.value().mimeType, "image/png");
    const PngHeader h = pngHeader(tileBytes.value().bytes);
    EXPECT_EQ(h.width, static_cast<std::uint32_t>(n));
    EXPECT_EQ(h.height, static_cast<std::uint32_t>(n));
    EXPECT_EQ(h.depth, 8);
    EXPECT_EQ(h.colourType, 2); // truecolour: RGB
  }
}

TEST(ReliefTile, NeighboursAreCutsOfOnePictureSoTheirEdgesShadeAlike) {
  const TileService service(island());
  const tiling::TileEvaluator evaluator(service.world());
  const tiling::TileScheme& scheme = service.scheme(tiling::SchemeKind::kWebMercator);
  const int n = 256, w = n + 2;
  const geometry::TileId east{kHills.z, kHills.x + 1, kHills.y};
  const tiling::SampleGrid gridA = scheme.borderedRasterGrid(kHills, n);
  const std::vector<double> a = evaluator.evaluate(gridA);
  const std::vector<double> b = evaluator.evaluate(scheme.borderedRasterGrid(east, n));
  // Each tile's border column holds the heights of the other's edge pixels.
  for (int j = 0; j < w; ++j) {
    const auto row = static_cast<std::size_t>(j * w);
    ASSERT_EQ(a[row + n + 1], b[row + 1]) << j;
    ASSERT_EQ(a[row + n], b[row]) << j;
  }
  // The two tiles side by side, bordered: one (2n + 2) × (n + 2) raster.
  const int W = 2 * n + 2;
  std::vector<double> both;
  for (int j = 0; j < w; ++j) {
    const auto row = static_cast<std::size_t>(j * w);
    both.insert(both.end(), a.begin() + static_cast<std::ptrdiff_t>(row),
                a.begin() + static_cast<std::ptrdiff_t>(row + n + 1));
    both.insert(both.end(), b.begin() + static_cast<std::ptrdiff_t>(row + 1),
                b.begin() + static_cast<std::ptrdiff_t>(row + w));
  }
  ASSERT_EQ(both.size(), static_cast<std::size_t>(W * w));
  const image::RgbImage whole = render::shadeRelief(both, 2 * n, n, gridA.rowSpacing);
  // Each tile's bytes are the PNG of its half of that picture.
  for (int half = 0; half < 2; ++half) {
    std::vector<std::uint8_t> pixels;
    for (int y = 0; y < n; ++y) {
      const auto start = whole.pixels.begin() + (y * 2 * n + half * n) * 3;
      pixels.insert(pixels.end(), start, start + n * 3);
    }
    const auto tile = service.render(
        {tiling::SchemeKind::kWebMercator, half ? east : kHills, TileFormat::kRelief, {}, {}});
    ASSERT_TRUE(tile.ok()) << tile.error().message;
    EXPECT_EQ(tile.value().bytes, encoding::encodeRgbPng(pixels, n, n).value()) << half;
  }
  // So the colours across the seam differ no more than across the columns inside a tile.
  auto columnStep = [&](int x) {
    long sum = 0;
    for (int y = 0; y < n; ++y)
      for (int k = 0; k < 3; ++k)
        sum += std::abs(whole.pixels[static_cast<std::size_t>((y * 2 * n + x) * 3 + k)] -
                        whole.pixels[static_cast<std::size_t>((y * 2 * n + x + 1) * 3 + k)]);
    return static_cast<double>(sum) / (3.0 * n);
  };
  double inside = 0;
  for (int x = 0; x + 1 < 2 * n; ++x)
    if (x != n - 1)
      inside = std::max(inside, columnStep(x));
  EXPECT_GT(inside, 0.0);
  EXPECT_LE(columnStep(n - 1), inside);
}

/// GET `target` on a fresh connection (the servers' tests' one-request client).
HttpResponse get(std::uint16_t port, const std::string& target, const std::string& extra = "") {
  return test_support::request(port, target, "GET", extra);
}

TEST(ReliefTile, IsServedLikeEveryOtherTile) {
  test_support::Running s; // the default island as "island", two workers
  const std::uint16_t port = s.port();
  const std::string path = "/worlds/island/tiles/12/1736/1494.relief";
  HttpResponse tile = get(port, test_support::versioned(port, path));
  ASSERT_EQ(tile.status, 200) << tile.body;
  EXPECT_EQ(tile.headers["content-type"], "image/png");
  EXPECT_EQ(tile.headers["access-control-allow-origin"], "*");
  EXPECT_EQ(tile.headers["cache-control"], "public, max-age=86400, immutable");
  EXPECT_NE(tile.headers["server-timing"].find("eval;dur="), std::string::npos);
  const std::string etag = tile.headers["etag"];
  ASSERT_FALSE(etag.empty());
  EXPECT_EQ(etag.front(), '"');
  const PngHeader h = pngHeader(tile.body);
  EXPECT_EQ(h.width, 256u);
  EXPECT_EQ(h.height, 256u);
  EXPECT_EQ(h.colourType, 2);
  // Its heightmap twin is another tile with another ETag.
  HttpResponse heights = get(port, "/worlds/island/tiles/12/1736/1494.png");
  EXPECT_EQ(heights.status, 200);
  EXPECT_NE(heights.headers["etag"], etag);
  // Conditional requests and every spelling of the default size: one tile, one ETag.
  HttpResponse again = get(port, path, "If-None-Match: " + etag + "\r\n");
  EXPECT_EQ(again.status, 304);
  EXPECT_TRUE(again.body.empty());
  HttpResponse spelled = get(port, path + "?size=256");
  EXPECT_EQ(spelled.headers["etag"], etag);
  EXPECT_EQ(spelled.body, tile.body);
  EXPECT_EQ(get(port, path, "If-None-Match: \"other\"\r\n").status, 200);
  // Other sizes and the local pyramid.
  HttpResponse small = get(port, path + "?size=64");
  EXPECT_EQ(small.status, 200);
  EXPECT_EQ(pngHeader(small.body).width, 64u);
  EXPECT_NE(small.headers["etag"], etag);
  EXPECT_EQ(get(port, "/worlds/island/local/2/1/2.relief").status, 200);
  // Bad sizes, a png-only query and tiles outside the grid.
  for (const std::string bad : {"?size=8", "?size=2000", "?size=abc", "?encoding=terrarium"})
    EXPECT_EQ(get(port, path + bad).status, 400) << bad;
  EXPECT_EQ(get(port, "/worlds/island/tiles/19/0/0.relief").status, 404);
  s.server.stop();
}

} // namespace
} // namespace strahler::app
