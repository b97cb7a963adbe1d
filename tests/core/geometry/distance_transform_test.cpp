#include "strahler/geometry/distance_transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace strahler::geometry {
namespace {

TEST(DistanceTransform, IsEuclidean) {
  std::vector<std::uint8_t> marked(7 * 5, 0);
  marked[2 * 7 + 3] = 1;
  const std::vector<float> d = distanceToMarked(7, 5, 10.0, marked);
  EXPECT_FLOAT_EQ(d[2 * 7 + 3], 0.0f);
  EXPECT_FLOAT_EQ(d[0], float(10.0 * std::sqrt(13.0)));
  EXPECT_FLOAT_EQ(d[4 * 7 + 6], float(10.0 * std::sqrt(13.0)));
}

TEST(DistanceTransform, IsInfiniteWithoutMarks) {
  EXPECT_TRUE(std::isinf(distanceToMarked(3, 3, 1.0, std::vector<std::uint8_t>(9, 0))[4]));
}

} // namespace
} // namespace strahler::geometry
