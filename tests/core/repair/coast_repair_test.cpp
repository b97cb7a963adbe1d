#include "strahler/repair/coast_repair.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace strahler::repair {
namespace {

using geometry::Ring;
using geometry::Vec2;

std::vector<InputPolygon> one(std::vector<Ring> rings) {
  return {InputPolygon{"polygon 0", std::move(rings)}};
}

RepairedCoast repaired(const std::vector<InputPolygon>& input) {
  auto result = repairCoastline(input);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().message);
  return result.ok() ? std::move(result).value() : RepairedCoast{};
}

std::size_t countKind(const RepairedCoast& r, ChangeKind kind) {
  return static_cast<std::size_t>(std::count_if(
      r.changes.begin(), r.changes.end(), [kind](const Change& c) { return c.kind == kind; }));
}

const Change* findKind(const RepairedCoast& r, ChangeKind kind) {
  for (const Change& c : r.changes)
    if (c.kind == kind)
      return &c;
  return nullptr;
}

std::string report(const RepairedCoast& r) {
  std::string text;
  for (const Change& c : r.changes)
    text += describe(c) + "\n";
  return text;
}

/// km² of one square degree at latitude `lat` on the 6,371 km sphere.
double squareDegreeKm2(double lat) {
  const double km = 6371.0 * 3.14159265358979323846 / 180.0;
  return km * km * std::cos(lat * 3.14159265358979323846 / 180.0);
}

const Ring kSquare{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
const Ring kLake{{1, 1}, {1, 2}, {2, 2}, {2, 1}}; // clockwise

TEST(CoastRepair, ValidCoastlineComesBackUnchangedWithNoReport) {
  const std::vector<InputPolygon> input{InputPolygon{"polygon 0", {kSquare, kLake}},
                                        InputPolygon{"polygon 1", {{{10, 0}, {11, 0}, {11, 1}}}}};
  const RepairedCoast r = repaired(input);
  EXPECT_TRUE(r.changes.empty()) << report(r);
  ASSERT_EQ(r.land.size(), 2u);
  EXPECT_EQ(r.land[0].outer, kSquare);
  ASSERT_EQ(r.land[0].holes.size(), 1u);
  EXPECT_EQ(r.land[0].holes[0], kLake);
  EXPECT_EQ(r.land[1].outer, input[1].rings[0]);
}

TEST(CoastRepair, ClockwiseRingIsReversedKeepingItsFirstVertex) {
  const Ring clockwise{{0, 0}, {0, 4}, {4, 4}, {4, 0}};
  const RepairedCoast r = repaired(one({clockwise}));
  ASSERT_EQ(r.changes.size(), 1u) << report(r);
  EXPECT_EQ(r.changes[0].kind, ChangeKind::kOrientation);
  EXPECT_EQ(r.changes[0].areaKm2, 0.0);
  EXPECT_NE(r.changes[0].description.find("polygon 0, ring 0: the ring runs clockwise"),
            std::string::npos);
  ASSERT_EQ(r.land.size(), 1u);
  EXPECT_EQ(r.land[0].outer, (Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}));
  // A counter-clockwise hole is reversed too.
  const Ring lakeCcw{{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  const RepairedCoast lake = repaired(one({kSquare, lakeCcw}));
  ASSERT_EQ(lake.changes.size(), 1u) << report(lake);
  EXPECT_NE(lake.changes[0].description.find("ring 1: the ring runs counter-clockwise"),
            std::string::npos);
  EXPECT_EQ(lake.land[0].holes[0], (Ring{{1, 1}, {1, 2}, {2, 2}, {2, 1}}));
}

TEST(CoastRepair, DuplicatePointsAreRemovedAndReported) {
  const Ring ring{{0, 0}, {4, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 4}, {0, 0}};
  const RepairedCoast r = repaired(one({ring}));
  EXPECT_EQ(countKind(r, ChangeKind::kDuplicatePoint), 3u) << report(r);
  EXPECT_EQ(r.changes.size(), 3u) << report(r);
  const Change* first = findKind(r, ChangeKind::kDuplicatePoint);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->lonLat, (Vec2{4, 0}));
  EXPECT_EQ(first->areaKm2, 0.0);
  EXPECT_NE(first->description.find("position 2 repeats position 1"), std::string::npos)
      << first->description;
  ASSERT_EQ(r.land.size(), 1u);
  EXPECT_EQ(r.land[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ(geometry::area(r.land), 16.0);
}

TEST(CoastRepair, SpikeTipIsRemoved) {
  // At (6, 2) the ring goes back along the segment it came by.
  const Ring ring{{0, 0}, {4, 0}, {4, 2}, {6, 2}, {5, 2}, {4, 3}, {0, 3}};
  const RepairedCoast r = repaired(one({ring}));
  ASSERT_EQ(r.changes.size(), 1u) << report(r);
  EXPECT_EQ(r.changes[0].kind, ChangeKind::kSpike);
  EXPECT_EQ(r.changes[0].lonLat, (Vec2{6, 2}));
  EXPECT_EQ(r.changes[0].areaKm2, 0.0);
  EXPECT_NE(r.changes[0].description.find("turns back on itself at position 3"), std::string::npos);
  ASSERT_EQ(r.land.size(), 1u);
  EXPECT_EQ(r.land[0].outer, (Ring{{0, 0}, {4, 0}, {4, 2}, {5, 2}, {4, 3}, {0, 3}}));
}

TEST(CoastRepair, BowtieKeepsBothLobesJoinedAtTheCrossing) {
  // Segments 0 ((0,0)-(2,2)) and 2 ((2,0)-(0,2)) cross at (1, 1).
  const Ring bowtie{{0, 0}, {2, 2}, {2, 0}, {0, 2}};
  const RepairedCoast r = repaired(one({bowtie}));
  const Change* crossing = findKind(r, ChangeKind::kSelfIntersection);
  ASSERT_NE(crossing, nullptr) << report(r);
  EXPECT_EQ(countKind(r, ChangeKind::kSelfIntersection), 1u) << report(r);
  EXPECT_NEAR(crossing->lonLat.x, 1.0, 1e-12);
  EXPECT_NEAR(crossing->lonLat.y, 1.0, 1e-12);
  EXPECT_NE(crossing->description.find("positions 0-1 and positions 2-3 cross"), std::string::npos)
      << crossing->description;
  EXPECT_NE(crossing->description.find("kept as land"), std::string::npos);
  // The lobe split off is one triangle of 1 square degree (at about 1.5 degrees north).
  EXPECT_NEAR(crossing->areaKm2, squareDegreeKm2(1.0), 0.01 * squareDegreeKm2(1.0));
  // The lobes touched at (1, 1): a rhombus of at most 10 m across joins them.
  const Change* pinch = findKind(r, ChangeKind::kPinch);
  ASSERT_NE(pinch, nullptr) << report(r);
  EXPECT_EQ(pinch->lonLat, crossing->lonLat);
  EXPECT_GT(pinch->areaKm2, 0.0);
  EXPECT_LT(pinch->areaKm2, 2e-4);
  ASSERT_EQ(r.land.size(), 1u) << report(r);
  EXPECT_TRUE(r.land[0].holes.empty());
  EXPECT_NEAR(geometry::area(r.land), 2.0, 1e-6);
  EXPECT_GT(geometry::signedArea(r.land[0].outer), 0.0);
}

TEST(CoastRepair, RingThroughOneVertexTwiceIsSplitThere) {
  // Two squares meeting at the corner (2, 2), drawn as one ring.
  const Ring figureEight{{0, 0}, {2, 0}, {2, 2}, {4, 2}, {4, 4}, {2, 4}, {2, 2}, {0, 2}};
  const RepairedCoast r = repaired(one({figureEight}));
  const Change* touch = findKind(r, ChangeKind::kSelfTouch);
  ASSERT_NE(touch, nullptr) << report(r);
  EXPECT_EQ(touch->lonLat, (Vec2{2, 2}));
  EXPECT_NE(touch->description.find("touch; the ring was split there"), std::string::npos)
      << touch->description;
  EXPECT_EQ(countKind(r, ChangeKind::kPinch), 1u) << report(r);
  ASSERT_EQ(r.land.size(), 1u);
  EXPECT_NEAR(geometry::area(r.land), 8.0, 1e-6);
}

TEST(CoastRepair, VertexOnAnotherSegmentIsSplitThere) {
  // (2, 0) lies on the first segment: two triangles that touch there.
  const Ring ring{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}};
  const RepairedCoast r = repaired(one({ring}));
  const Change* touch = findKind(r, ChangeKind::kSelfTouch);
  ASSERT_NE(touch, nullptr) << report(r);
  EXPECT_EQ(touch->lonLat, (Vec2{2, 0}));
  ASSERT_EQ(r.land.size(), 1u) << report(r);
  EXPECT_NEAR(geometry::area(r.land), 8.0, 1e-6);
}

TEST(CoastRepair, LoopTurningInwardBecomesWater) {
  // A ring that curls into itself: the 2 x 4 loop lies inside the rest, so the even-odd rule
  // makes it a lake, joined to the shore where the ring crossed. The rest is the 10 x 10
  // square without the notch [0, 2] x [0.5, 2].
  const Ring curl{{0, 0}, {10, 0}, {10, 10}, {0, 10},  {0, 2},
                  {4, 2}, {4, 6},  {2, 6},   {2, 0.5}, {0, 0.5}};
  // Segment (2, 6)-(2, 0.5) crosses (0, 2)-(4, 2) at (2, 2).
  const RepairedCoast r = repaired(one({curl}));
  const Change* crossing = findKind(r, ChangeKind::kSelfIntersection);
  ASSERT_NE(crossing, nullptr) << report(r);
  EXPECT_EQ(crossing->lonLat, (Vec2{2, 2}));
  EXPECT_NE(crossing->description.find("left as water"), std::string::npos) << report(r);
  EXPECT_NEAR(geometry::area(r.land), 100.0 - 3.0 - 8.0, 1e-3) << report(r);
}

TEST(CoastRepair, RingWithoutAreaIsRemoved) {
  const Ring flat{{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  const std::vector<InputPolygon> input{InputPolygon{"polygon 0", {kSquare}},
                                        InputPolygon{"polygon 1", {flat}}};
  const RepairedCoast r = repaired(input);
  EXPECT_EQ(countKind(r, ChangeKind::kDegenerateRing), 1u) << report(r);
  EXPECT_EQ(r.land.size(), 1u);
  // With nothing else, nothing is left: an error, not an empty coastline.
  auto none = repairCoastline(one({flat}));
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.error().code, base::ErrorCode::kInvalidInput);
  EXPECT_NE(none.error().message.find("nothing is left"), std::string::npos);
}

TEST(CoastRepair, OverlappingPolygonsAreUnited) {
  const std::vector<InputPolygon> input{
      InputPolygon{"polygon 0", {kSquare}},
      InputPolygon{"polygon 1", {{{3, 3}, {6, 3}, {6, 6}, {3, 6}}}}};
  const RepairedCoast r = repaired(input);
  const Change* overlap = findKind(r, ChangeKind::kOverlap);
  ASSERT_NE(overlap, nullptr) << report(r);
  EXPECT_NE(overlap->description.find("polygon 0 and polygon 1 overlap"), std::string::npos);
  EXPECT_NEAR(overlap->lonLat.x, 3.5, 1e-9);
  EXPECT_NEAR(overlap->areaKm2, squareDegreeKm2(3.5), 0.01 * squareDegreeKm2(3.5));
  ASSERT_EQ(r.land.size(), 1u);
  EXPECT_NEAR(geometry::area(r.land), 16.0 + 9.0 - 1.0, 1e-9);
}

TEST(CoastRepair, HoleReachingOutsideIsCutToTheLand) {
  const Ring hole{{3, 1}, {3, 2}, {6, 2}, {6, 1}}; // clockwise, half outside
  const RepairedCoast r = repaired(one({kSquare, hole}));
  const Change* overlap = findKind(r, ChangeKind::kOverlap);
  ASSERT_NE(overlap, nullptr) << report(r);
  EXPECT_NE(overlap->description.find("ring 1: the hole reaches outside"), std::string::npos);
  ASSERT_EQ(r.land.size(), 1u);
  EXPECT_NEAR(geometry::area(r.land), 16.0 - 1.0, 1e-9);
}

TEST(CoastRepair, SameInputSameOutput) {
  const std::vector<InputPolygon> input{
      InputPolygon{"polygon 0", {{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}},
      InputPolygon{"polygon 1", {{{5, 0}, {5, 0}, {7, 0}, {8, 0}, {7, 0}, {7, 2}}}}};
  const RepairedCoast a = repaired(input), b = repaired(input);
  ASSERT_EQ(a.land.size(), b.land.size());
  for (std::size_t p = 0; p < a.land.size(); ++p) {
    EXPECT_EQ(a.land[p].outer, b.land[p].outer);
    EXPECT_EQ(a.land[p].holes, b.land[p].holes);
  }
  EXPECT_EQ(report(a), report(b));
}

TEST(CoastRepair, TooManyCrossingsAreRefused) {
  // A zigzag whose every tooth crosses the return stroke.
  Ring zigzag;
  for (int i = 0; i <= 40; ++i)
    zigzag.push_back({i * 0.1, (i % 2) ? 1.0 : -1.0});
  zigzag.push_back({4.0, 0.0});
  zigzag.push_back({0.0, 0.0});
  RepairLimits limits;
  limits.maxCrossings = 10;
  auto r = repairCoastline(one({zigzag}), limits);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, base::ErrorCode::kLimitExceeded);
  EXPECT_NE(r.error().message.find("polygon 0, ring 0: more than 10 self-intersections"),
            std::string::npos)
      << r.error().message;
}

TEST(CoastRepair, DescribeGivesKindPlaceAndArea) {
  const Change change{ChangeKind::kSelfIntersection,
                      {-16.482761, 63.902229},
                      0.04133,
                      "polygon 0, ring 0: segments cross"};
  EXPECT_EQ(describe(change), "self-intersection at (-16.48276, 63.90223), 0.04133 km²: polygon "
                              "0, ring 0: segments cross");
}

} // namespace
} // namespace strahler::repair
