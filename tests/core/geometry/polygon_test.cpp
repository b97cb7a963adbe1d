#include "strahler/geometry/distance.h"
#include "strahler/geometry/polygon.h"

#include <gtest/gtest.h>

namespace strahler::geometry {
namespace {

Ring square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

TEST(Polygon, AreaSubtractsHoles) {
  Polygon p{square(0, 0, 10), {square(2, 2, 3)}};
  orient(p);
  EXPECT_DOUBLE_EQ(area(p), 100.0 - 9.0);
  EXPECT_GT(signedArea(p.outer), 0.0);
  EXPECT_LT(signedArea(p.holes[0]), 0.0);
}

TEST(Polygon, ContainsHonoursHoles) {
  const Polygon p{square(0, 0, 10), {square(2, 2, 3)}};
  EXPECT_TRUE(contains(p, {1, 1}));
  EXPECT_FALSE(contains(p, {3, 3}));
  EXPECT_FALSE(contains(p, {11, 1}));
}

TEST(Polygon, CentroidOfSquareIsItsCentre) {
  const MultiPolygon m{{square(0, 0, 4), {}}};
  const Vec2 c = centroid(m);
  EXPECT_NEAR(c.x, 2.0, 1e-12);
  EXPECT_NEAR(c.y, 2.0, 1e-12);
}

TEST(ClipToConvex, KeepsExactAreaOfConcaveIntersections) {
  // A U shape cut by a window across both arms: two pieces of 1x2 each.
  const Ring u{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  const Ring window = square(-1, 1, 5); // y in [1, 4]
  const Ring clipped = clipToConvex(u, window);
  EXPECT_NEAR(std::abs(signedArea(clipped)), 4.0, 1e-12);
  EXPECT_TRUE(clipToConvex(u, square(10, 10, 1)).empty());
}

TEST(Distance, SegmentQueries) {
  EXPECT_DOUBLE_EQ(pointSegmentDistance({0, 1}, {-1, 0}, {1, 0}), 1.0);
  EXPECT_DOUBLE_EQ(pointSegmentDistance({3, 0}, {-1, 0}, {1, 0}), 2.0);
  EXPECT_TRUE(segmentsIntersect({0, 0}, {2, 2}, {0, 2}, {2, 0}));
  EXPECT_FALSE(segmentsIntersect({0, 0}, {1, 0}, {0, 1}, {1, 1}));
  EXPECT_DOUBLE_EQ(segmentSegmentDistance({0, 0}, {1, 0}, {0, 1}, {1, 1}), 1.0);
  EXPECT_DOUBLE_EQ(segmentSegmentDistance({0, 0}, {2, 2}, {0, 2}, {2, 0}), 0.0);
}

} // namespace
} // namespace strahler::geometry
