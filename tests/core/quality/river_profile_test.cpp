#include "strahler/quality/river_profile.h"

#include <gtest/gtest.h>

#include <vector>

namespace strahler::quality {
namespace {

using geometry::Vec2;
using Lines = std::vector<std::vector<Vec2>>;

TEST(RiverProfile, DescendingRiverHasNoViolation) {
  const RiverProfileReport report = checkRiversDescend(
      Lines{{{0, 0}, {1000, 0}}}, [](Vec2 p) { return 100.0 - p.x / 10.0; }, 10.0, 0.0);
  EXPECT_EQ(report.samples, 101u);
  EXPECT_EQ(report.violations, 0u);
  EXPECT_DOUBLE_EQ(report.worstRise, 0.0);
}

/// Flat at 50 m except a 1 m step on x in [500, 520).
double bumpAt500(Vec2 p) {
  return p.x >= 500.0 && p.x < 520.0 ? 51.0 : 50.0;
}

TEST(RiverProfile, BumpIsReportedWhereItRises) {
  const RiverProfileReport report =
      checkRiversDescend(Lines{{{0, 0}, {1000, 0}}}, bumpAt500, 10.0, 0.5);
  EXPECT_EQ(report.violations, 2u) << "samples at x = 500 and 510";
  EXPECT_NEAR(report.worstRise, 1.0, 1e-12);
  EXPECT_NEAR(report.worstAt.x, 500.0, 1e-9);
  EXPECT_NEAR(report.worstAt.y, 0.0, 1e-9);
}

TEST(RiverProfile, BumpWithinToleranceIsAccepted) {
  const RiverProfileReport report =
      checkRiversDescend(Lines{{{0, 0}, {1000, 0}}}, bumpAt500, 10.0, 1.5);
  EXPECT_EQ(report.violations, 0u);
  EXPECT_DOUBLE_EQ(report.worstRise, 0.0);
}

TEST(RiverProfile, RiseIsMeasuredFromTheLowestPointUpstream) {
  // Down to 10 m at x = 100, then up 0.3 m per 10 m sample: each step is within the 0.5 m
  // tolerance but the climb from the low point is not.
  const auto height = [](Vec2 p) {
    return p.x <= 100.0 ? 20.0 - p.x / 10.0 : 10.0 + 0.03 * (p.x - 100.0);
  };
  const RiverProfileReport report =
      checkRiversDescend(Lines{{{0, 0}, {200, 0}}}, height, 10.0, 0.5);
  EXPECT_EQ(report.violations, 9u) << "x = 120 .. 200";
  EXPECT_NEAR(report.worstRise, 3.0, 1e-9);
  EXPECT_NEAR(report.worstAt.x, 200.0, 1e-9);
}

TEST(RiverProfile, SamplesFollowThePolylineAndIncludeBothEnds) {
  std::vector<Vec2> sampled;
  const auto record = [&](Vec2 p) {
    sampled.push_back(p);
    return 0.0;
  };
  const RiverProfileReport report =
      checkRiversDescend(Lines{{{0, 0}, {15, 0}, {15, 10}}}, record, 10.0, 0.0);
  EXPECT_EQ(report.samples, 4u);
  ASSERT_EQ(sampled.size(), 4u);
  EXPECT_EQ(sampled[0], (Vec2{0, 0}));
  EXPECT_EQ(sampled[1], (Vec2{10, 0}));
  EXPECT_NEAR(sampled[2].x, 15.0, 1e-12);
  EXPECT_NEAR(sampled[2].y, 5.0, 1e-12);
  EXPECT_EQ(sampled[3], (Vec2{15, 10}));
}

TEST(RiverProfile, EndIsNotSampledTwiceWhenTheSpacingDividesTheLength) {
  const RiverProfileReport report = checkRiversDescend(
      Lines{{{0, 0}, {0.3, 0}, {0.6, 0}, {0.7, 0}}}, [](Vec2) { return 0.0; }, 0.1, 0.0);
  EXPECT_EQ(report.samples, 8u);
}

TEST(RiverProfile, EachCentrelineStartsAfresh) {
  // The second river is higher than where the first ends, which is not a violation.
  const auto height = [](Vec2 p) { return p.y > 0.0 ? 50.0 : 100.0 - p.x / 10.0; };
  const RiverProfileReport report =
      checkRiversDescend(Lines{{{0, 0}, {1000, 0}}, {{0, 10}, {100, 10}}}, height, 10.0, 0.0);
  EXPECT_EQ(report.samples, 101u + 11u);
  EXPECT_EQ(report.violations, 0u);
}

TEST(RiverProfile, DegenerateCentrelines) {
  const RiverProfileReport report = checkRiversDescend(
      Lines{{}, {{5, 5}}, {{1, 1}, {1, 1}}}, [](Vec2) { return 3.0; }, 10.0, 0.0);
  EXPECT_EQ(report.samples, 2u) << "one sample per non-empty line";
  EXPECT_EQ(report.violations, 0u);
}

} // namespace
} // namespace strahler::quality
