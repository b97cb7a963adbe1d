// Which tiles `strahler export` writes, and how it reads --zooms and --bbox.
#include "export_plan.h"
#include "result_matchers.h"

#include <gtest/gtest.h>

namespace {

using namespace strahler::app;

TEST(ExportPlan, ParsesZoomRangesAndSingleZooms) {
  EXPECT_EQ(strahler::test_support::valueOf(parseZoomRange("0-14", 18)), (std::pair{0, 14}));
  EXPECT_EQ(strahler::test_support::valueOf(parseZoomRange("7", 18)), (std::pair{7, 7}));
  for (const char* bad : {"", "-", "3-", "-3", "a-b", "1-2-3", "5-3", "0-19", " 1-2", "1.5"})
    EXPECT_FALSE(parseZoomRange(bad, 18).ok()) << bad;
}

TEST(ExportPlan, ParsesBoxesAndRefusesMalformedOnes) {
  STRAHLER_ASSIGN_OR_ASSERT(const LonLatBox b, parseBbox("2.3,39.2,3.5,40.1"));
  EXPECT_DOUBLE_EQ(b.west, 2.3);
  EXPECT_DOUBLE_EQ(b.north, 40.1);
  for (const char* bad : {"", "1,2,3", "1,2,3,4,5", "1,2,x,4", "3,2,1,4", "1,4,3,2", "-181,0,0,1",
                          "0,-91,1,0", "1,,3,4", "nan,1,2,3"})
    EXPECT_FALSE(parseBbox(bad).ok()) << bad;
}

TEST(ExportPlan, IntersectsBoxes) {
  const auto c = intersect({0, 0, 10, 10}, {5, -5, 20, 5});
  ASSERT_TRUE(c);
  EXPECT_EQ(describe(*c), "5.00000,0.00000,10.00000,5.00000");
  EXPECT_FALSE(intersect({0, 0, 1, 1}, {2, 2, 3, 3}));
  EXPECT_FALSE(intersect({0, 0, 1, 1}, {1, 0, 2, 1})) << "touching edges do not overlap";
}

TEST(ExportPlan, TileRectanglesCoverTheBoxAndStopAtTileBorders) {
  // The north-east quarter of the world (lon 0..180, lat 0..85.05): one tile at z1, four at z2.
  const auto rects = tileRects({0.0, 0.0, 180.0, 85.0511287798066}, 0, 2);
  ASSERT_EQ(rects.size(), 3u);
  EXPECT_EQ(rects[0].count(), 1u);
  EXPECT_EQ(rects[1].x0, 1u);
  EXPECT_EQ(rects[1].x1, 1u);
  EXPECT_EQ(rects[1].y0, 0u);
  EXPECT_EQ(rects[1].y1, 0u) << "the equator is a tile border: row 1 is not touched";
  EXPECT_EQ(rects[2].count(), 4u);
  EXPECT_EQ(countTiles(rects), 6u);
  // A box of 0.01° touches at most 2 × 2 tiles while tiles are wider than it (z ≤ 8), and
  // about (0.01° / tile width)² at z18 (tiles 0.00137° wide: 8 columns, 9-10 rows).
  for (const TileRect& r : tileRects({2.60, 39.55, 2.61, 39.56}, 0, 8))
    EXPECT_LE(r.count(), 4u) << "zoom " << r.z;
  const TileRect deep = tileRects({2.60, 39.55, 2.61, 39.56}, 18, 18).front();
  EXPECT_GE(deep.x1 - deep.x0 + 1, 8u);
  EXPECT_LE(deep.x1 - deep.x0 + 1, 9u);
}

TEST(ExportPlan, HilbertOrderAscendsAndHoldsEveryTile) {
  const auto rects = tileRects({-10.0, 35.0, 5.0, 45.0}, 3, 9);
  const auto ids = hilbertOrder(rects);
  ASSERT_EQ(ids.size(), countTiles(rects));
  for (std::size_t i = 1; i < ids.size(); ++i)
    ASSERT_LT(ids[i - 1], ids[i]);
}

} // namespace
