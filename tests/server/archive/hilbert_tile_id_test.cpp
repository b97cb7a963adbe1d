// Tile ids quoted from the PMTiles v3 spec ("z0 → 0, z1 0/0/0 → 1 ...") and, for deep zooms,
// the reference implementation (npm pmtiles 4.5.0, zxyToTileId).
#include "hilbert_tile_id.h"

#include <gtest/gtest.h>

namespace {

using strahler::archive::TileCoord;
using strahler::archive::tileIdToZxy;
using strahler::archive::zxyToTileId;

TEST(HilbertTileId, MatchesTheSpecAtLowZooms) {
  EXPECT_EQ(zxyToTileId({0, 0, 0}), 0u);
  EXPECT_EQ(zxyToTileId({1, 0, 0}), 1u);
  EXPECT_EQ(zxyToTileId({1, 0, 1}), 2u);
  EXPECT_EQ(zxyToTileId({1, 1, 1}), 3u);
  EXPECT_EQ(zxyToTileId({1, 1, 0}), 4u);
  EXPECT_EQ(zxyToTileId({2, 0, 0}), 5u);
  EXPECT_EQ(zxyToTileId({2, 3, 0}), 20u);
  EXPECT_EQ(zxyToTileId({3, 0, 0}), 21u);
  EXPECT_EQ(zxyToTileId({3, 7, 7}), 63u);
}

TEST(HilbertTileId, MatchesTheReferenceImplementationAtDeepZooms) {
  EXPECT_EQ(zxyToTileId({12, 3423, 1763}), 19078479u);
  EXPECT_EQ(zxyToTileId({18, 140000, 97000}), 81222129685u);
  EXPECT_EQ(zxyToTileId({26, 1234567, 7654321}), 1569498637851243u);
}

TEST(HilbertTileId, InverseRoundTripsEveryTileOfZoomsZeroToFive) {
  std::uint64_t expected = 0;
  for (int z = 0; z <= 5; ++z) {
    // Ids are dense: zoom z takes the 4^z ids after those of the lower zooms.
    std::vector<bool> seen(std::size_t{1} << (2 * z), false);
    for (std::uint32_t y = 0; y < (1u << z); ++y)
      for (std::uint32_t x = 0; x < (1u << z); ++x) {
        const std::uint64_t id = zxyToTileId({z, x, y});
        ASSERT_GE(id, expected);
        seen.at(id - expected) = true;
        EXPECT_EQ(tileIdToZxy(id), (TileCoord{z, x, y}));
      }
    for (bool s : seen)
      EXPECT_TRUE(s);
    expected += std::uint64_t{1} << (2 * z);
  }
  EXPECT_EQ(tileIdToZxy(1569498637851243u), (TileCoord{26, 1234567, 7654321}));
}

} // namespace
