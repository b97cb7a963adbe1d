// Tile rows (tile_id.h): the flip between XYZ rows (from the north) and TMS rows (from the
// south).
#include "strahler/geometry/tile_id.h"

#include <gtest/gtest.h>

namespace strahler::geometry {
namespace {

TEST(FlipRow, CountsFromTheOtherPoleAndIsItsOwnInverse) {
  EXPECT_EQ(flipRow(0, 0), 0);
  EXPECT_EQ(flipRow(1, 0), 1);
  EXPECT_EQ(flipRow(3, 2), 5);
  EXPECT_EQ(flipRow(30, 0), (std::int64_t{1} << 30) - 1);
  for (int z : {0, 5, 17, 40})
    for (std::int64_t y : {std::int64_t{0}, (std::int64_t{1} << z) - 1, std::int64_t{1} << z >> 1})
      EXPECT_EQ(flipRow(z, flipRow(z, y)), y) << z << " " << y;
  static_assert(flipRow(2, 1) == 2);
}

} // namespace
} // namespace strahler::geometry
