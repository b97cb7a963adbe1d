// Clipping and rounding of vector tile geometry.
#include "strahler/vector_tile/tile_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace strahler::vector_tile {
namespace {

using geometry::Vec2;

constexpr ClipBox kBox{-64.0, 4160.0};

TEST(TileGeometry, ALineThatLeavesAndComesBackIsTwoPieces) {
  const std::vector<Vec2> line = {{0, 0}, {5000, 0}, {5000, 100}, {0, 100}};
  const auto pieces = clipLine(line, kBox);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0], (std::vector<Vec2>{{0, 0}, {4160, 0}}));
  EXPECT_EQ(pieces[1], (std::vector<Vec2>{{4160, 100}, {0, 100}}));
}

TEST(TileGeometry, ALineInsideIsKeptWhole) {
  const std::vector<Vec2> line = {{0, 0}, {10, 10}, {20, 0}};
  const auto pieces = clipLine(line, kBox);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0], line);
  EXPECT_TRUE(clipLine(std::vector<Vec2>{{-500, -500}, {-400, 5000}}, kBox).empty());
}

TEST(TileGeometry, ARingAroundTheBoxBecomesTheBox) {
  const std::vector<Vec2> ring = {{-1000, -1000}, {9000, -1000}, {9000, 9000}, {-1000, 9000}};
  const auto clipped = clipRing(ring, kBox);
  EXPECT_DOUBLE_EQ(std::abs(ringArea2(clipped)), 2.0 * 4224.0 * 4224.0);
  EXPECT_TRUE(clipRing(std::vector<Vec2>{{-900, -900}, {-800, -900}, {-800, -800}}, kBox).empty());
}

TEST(TileGeometry, PointsAreSimplifiedAndRounded) {
  const std::vector<Vec2> line = {{0.2, 0.2}, {50.1, 0.4}, {100.4, -0.1}};
  EXPECT_EQ(toTilePoints(line, 1.0, false), (std::vector<Point>{{0, 0}, {100, 0}}));
  const std::vector<Vec2> ring = {{0, 0}, {10, 0}, {10, 10}, {0.3, 0.2}};
  EXPECT_EQ(toTilePoints(ring, 0.0, true), (std::vector<Point>{{0, 0}, {10, 0}, {10, 10}}));
}

} // namespace
} // namespace strahler::vector_tile
