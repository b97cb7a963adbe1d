#include "strahler/tiling/tile_scheme.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace strahler::tiling {
namespace {

using geometry::Vec2;

bool sameBits(Vec2 a, Vec2 b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(TileScheme, KnowsWhichTilesExist) {
  const TileScheme web = TileScheme::webMercator(geometry::LocalProjection(2.9, 39.6));
  EXPECT_TRUE(web.contains({0, 0, 0}));
  EXPECT_TRUE(web.contains({18, (1 << 18) - 1, 5}));
  EXPECT_FALSE(web.contains({19, 0, 0}));
  EXPECT_FALSE(web.contains({3, 8, 0}));
  EXPECT_FALSE(web.contains({3, 0, -1}));
  EXPECT_FALSE(web.contains({-1, 0, 0}));
  const TileScheme local = TileScheme::local({0, 0}, 65536.0);
  EXPECT_EQ(local.maxZoom(), 9); // 65536 / 2^9 = 128 m tiles: 0.5 m per sample at 256
}

TEST(TileScheme, LocalTilesSplitTheRootSquare) {
  const TileScheme s = TileScheme::local({1000, 2000}, 4096.0);
  const geometry::Aabb root = s.localBounds({0, 0, 0});
  EXPECT_EQ(root.min, (Vec2{-1048, -48}));
  const geometry::Aabb nw = s.localBounds({1, 0, 0}); // y counts rows from the north
  EXPECT_EQ(nw.min, (Vec2{-1048, 2000}));
  EXPECT_EQ(nw.max, (Vec2{1000, 4048}));
}

TEST(TileScheme, RasterSamplesArePixelCentres) {
  const TileScheme s = TileScheme::local({0, 0}, 1024.0);
  const SampleGrid g = s.rasterGrid({1, 1, 0}, 4); // north-east quarter, 128 m pixels
  ASSERT_EQ(g.points.size(), 16u);
  EXPECT_EQ(g.points[0], (Vec2{64, 448})); // row 0 is the northern row
  EXPECT_EQ(g.points[15], (Vec2{448, 64}));
  EXPECT_EQ(g.rowSpacing[0], 128.0);
}

TEST(TileScheme, MeshNeighboursShareTheirEdgeSamplesBitForBit) {
  for (const TileScheme& s : {TileScheme::local({123.4, -56.7}, 48000.0),
                              TileScheme::webMercator(geometry::LocalProjection(-27.35, 43.72))}) {
    const int z = 12, n = 16;
    const std::int64_t x = s.kind() == SchemeKind::kLocal ? 1000 : 1736,
                       y = s.kind() == SchemeKind::kLocal ? 2000 : 1487;
    const SampleGrid a = s.meshGrid({z, x, y}, n), east = s.meshGrid({z, x + 1, y}, n),
                     south = s.meshGrid({z, x, y + 1}, n);
    const int w = n + 3;
    for (int j = 1; j <= n + 1; ++j) {
      // a's east edge (column n + 1) is east's west edge (column 1).
      ASSERT_TRUE(sameBits(a.points[j * w + n + 1], east.points[j * w + 1]));
    }
    for (int i = 1; i <= n + 1; ++i) {
      // a's south edge (row 1, rows run south to north) is south's north edge (row n + 1).
      ASSERT_TRUE(sameBits(a.points[1 * w + i], south.points[(n + 1) * w + i]));
      ASSERT_EQ(a.rowSpacing[1], south.rowSpacing[n + 1]);
    }
  }
}

TEST(TileScheme, BorderedRasterGridsHoldTheTileAndItsNeighboursEdgePixels) {
  for (const TileScheme& s : {TileScheme::local({123.4, -56.7}, 48000.0),
                              TileScheme::webMercator(geometry::LocalProjection(-27.35, 43.72))}) {
    const int z = 12, n = 16, w = n + 2;
    const std::int64_t x = s.kind() == SchemeKind::kLocal ? 1000 : 1736,
                       y = s.kind() == SchemeKind::kLocal ? 2000 : 1487;
    const SampleGrid b = s.borderedRasterGrid({z, x, y}, n), tile = s.rasterGrid({z, x, y}, n),
                     east = s.rasterGrid({z, x + 1, y}, n), west = s.rasterGrid({z, x - 1, y}, n),
                     north = s.rasterGrid({z, x, y - 1}, n), south = s.rasterGrid({z, x, y + 1}, n);
    ASSERT_EQ(b.width, w);
    ASSERT_EQ(b.height, w);
    ASSERT_EQ(b.points.size(), static_cast<std::size_t>(w * w));
    ASSERT_EQ(b.rowSpacing.size(), static_cast<std::size_t>(w));
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i)
        ASSERT_TRUE(sameBits(b.points[(j + 1) * w + i + 1], tile.points[j * n + i]))
            << i << "," << j;
      ASSERT_EQ(b.rowSpacing[j + 1], tile.rowSpacing[j]);
      // The west and east border columns are the neighbours' edge columns.
      ASSERT_TRUE(sameBits(b.points[(j + 1) * w], west.points[j * n + n - 1]));
      ASSERT_TRUE(sameBits(b.points[(j + 1) * w + n + 1], east.points[j * n]));
    }
    for (int i = 0; i < n; ++i) {
      // The north and south border rows are the neighbours' edge rows.
      ASSERT_TRUE(sameBits(b.points[i + 1], north.points[(n - 1) * n + i]));
      ASSERT_TRUE(sameBits(b.points[(n + 1) * w + i + 1], south.points[i]));
    }
    EXPECT_EQ(b.rowSpacing[0], north.rowSpacing[n - 1]);
    EXPECT_EQ(b.rowSpacing[n + 1], south.rowSpacing[0]);
  }
}

TEST(TileScheme, WebSamplesMatchTheProjectionOfTheirLonLat) {
  const geometry::LocalProjection projection(2.95, 39.6);
  const TileScheme s = TileScheme::webMercator(projection);
  const geometry::TileId tile{10, 520, 391};
  const SampleGrid g = s.rasterGrid(tile, 8);
  const double n = std::ldexp(1.0, tile.z);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const double lon = (static_cast<double>(tile.x) + (i + 0.5) / 8) / n * 360.0 - 180.0;
      const double lat =
          std::atan(std::sinh(M_PI * (1 - 2 * (static_cast<double>(tile.y) + (j + 0.5) / 8) / n))) *
          180.0 / M_PI;
      const Vec2 expected = projection.forward({lon, lat});
      EXPECT_NEAR(g.points[j * 8 + i].x, expected.x, 1e-6);
      EXPECT_NEAR(g.points[j * 8 + i].y, expected.y, 1e-6);
    }
  // Spacing on the ground: the tile's mercator pixel scaled by cos(latitude).
  EXPECT_NEAR(g.rowSpacing[0], 2 * M_PI * kWebMercatorRadius / n / 8 * std::cos(39.6 * M_PI / 180),
              300.0);
}

TEST(TileScheme, GeographicTilesHaveTwoRootsAndSquareDegreeBounds) {
  const TileScheme geo = TileScheme::geographic(geometry::LocalProjection(2.9, 39.6));
  EXPECT_EQ(geo.kind(), SchemeKind::kGeographic);
  EXPECT_EQ(geo.maxZoom(), TileScheme::kMaxGeographicZoom);
  EXPECT_TRUE(geo.contains({0, 1, 0}));
  EXPECT_FALSE(geo.contains({0, 2, 0}));
  EXPECT_FALSE(geo.contains({0, 0, 1}));
  EXPECT_TRUE(geo.contains({3, 15, 7}));
  EXPECT_FALSE(geo.contains({3, 16, 7}));
  EXPECT_FALSE(geo.contains({TileScheme::kMaxGeographicZoom + 1, 0, 0}));
  const geometry::Aabb east = geo.geographicBounds({0, 1, 0});
  EXPECT_EQ(east.min.x, 0.0);
  EXPECT_EQ(east.max.x, 180.0);
  EXPECT_EQ(east.min.y, -90.0);
  EXPECT_EQ(east.max.y, 90.0);
  // Row 0 is the northernmost: level 2's row 1 spans latitudes 0..45.
  const geometry::Aabb t = geo.geographicBounds({2, 4, 1});
  EXPECT_EQ(t.min.x, 0.0);
  EXPECT_EQ(t.max.x, 45.0);
  EXPECT_EQ(t.min.y, 0.0);
  EXPECT_EQ(t.max.y, 45.0);
}

TEST(TileScheme, GeographicMeshGridsShareTheirEdgeSamplesWithTheirNeighbours) {
  const geometry::LocalProjection projection(2.9, 39.6);
  const TileScheme geo = TileScheme::geographic(projection);
  const int quads = 16, n = quads + 3;
  const geometry::TileId a{12, 4129, 1133}, east{12, 4130, 1133}, north{12, 4129, 1132};
  const SampleGrid ga = geo.meshGrid(a, quads), ge = geo.meshGrid(east, quads),
                   gn = geo.meshGrid(north, quads);
  ASSERT_EQ(ga.width, n);
  ASSERT_EQ(ga.points.size(), static_cast<std::size_t>(n * n));
  // Row 0 is the south border; sample (1, 1) is the tile's south-west corner.
  const geometry::Aabb box = geo.geographicBounds(a);
  const Vec2 corner = projection.inverse(ga.points[static_cast<std::size_t>(n + 1)]);
  EXPECT_NEAR(corner.x, box.min.x, 1e-9);
  EXPECT_NEAR(corner.y, box.min.y, 1e-9);
  for (int j = 0; j < n; ++j) {
    // a's east edge column (quads + 1) is the east neighbour's west edge column (1).
    EXPECT_TRUE(sameBits(ga.points[static_cast<std::size_t>(j * n + quads + 1)],
                         ge.points[static_cast<std::size_t>(j * n + 1)]));
    // a's north edge row (quads + 1) is the north neighbour's south edge row (1).
    EXPECT_TRUE(sameBits(ga.points[static_cast<std::size_t>((quads + 1) * n + j)],
                         gn.points[static_cast<std::size_t>(n + j)]));
  }
  EXPECT_EQ(ga.rowSpacing, ge.rowSpacing);
  EXPECT_NEAR(ga.rowSpacing[0], 0.25 * 180.0 / 4096 / quads * 3.14159265358979 / 180 * 6371008.8,
              1e-6);
}

} // namespace
} // namespace strahler::tiling
