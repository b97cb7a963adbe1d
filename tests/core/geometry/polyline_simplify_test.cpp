#include "strahler/geometry/distance.h"
#include "strahler/geometry/polyline_simplify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace strahler::geometry {
namespace {

TEST(SimplifyPolyline, KeepsShortPolylinesWhole) {
  EXPECT_TRUE(simplifyPolyline({}, 1.0).empty());
  const std::vector<Vec2> two{{0, 0}, {5, 5}};
  EXPECT_EQ(simplifyPolyline(two, 100.0), (std::vector<std::size_t>{0, 1}));
}

TEST(SimplifyPolyline, DropsCollinearPointsAndKeepsCorners) {
  const std::vector<Vec2> points{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}};
  EXPECT_EQ(simplifyPolyline(points, 0.01), (std::vector<std::size_t>{0, 3, 5}));
}

TEST(SimplifyPolyline, EveryDroppedPointIsWithinTheToleranceOfTheKeptPolyline) {
  std::vector<Vec2> wave;
  for (int i = 0; i <= 400; ++i) {
    const double x = 5.0 * i;
    wave.push_back({x, 40.0 * std::sin(2.0 * std::numbers::pi * x / 300.0)});
  }
  const double tolerance = 2.0;
  const std::vector<std::size_t> kept = simplifyPolyline(wave, tolerance);
  ASSERT_GE(kept.size(), 2u);
  EXPECT_EQ(kept.front(), 0u);
  EXPECT_EQ(kept.back(), wave.size() - 1);
  EXPECT_LT(kept.size(), wave.size() / 2);
  for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
    ASSERT_LT(kept[k], kept[k + 1]);
    for (std::size_t i = kept[k] + 1; i < kept[k + 1]; ++i)
      ASSERT_LE(pointSegmentDistance(wave[i], wave[kept[k]], wave[kept[k + 1]]), tolerance);
  }
}

} // namespace
} // namespace strahler::geometry
