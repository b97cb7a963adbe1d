#include "strahler/geometry/distance.h"
#include "strahler/primitives/meander_curve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace strahler::primitives {
namespace {

using geometry::Vec2;

constexpr double kDegree = std::numbers::pi / 180.0;

double turn(Vec2 a, Vec2 b) {
  return std::abs(std::atan2(cross(a, b), dot(a, b)));
}

double polylineLength(const std::vector<Vec2>& points) {
  double total = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i)
    total += distance(points[i - 1], points[i]);
  return total;
}

TEST(MeanderCurve, SinuosityOfASineGeneratedWaveIsOneOverJ0) {
  // Langbein & Leopold 1966: the valley length of a wave is its arc length times J0(ω).
  for (const double omega : {0.2, 1.0, 1.3, 1.6, 1.9})
    EXPECT_NEAR(meanderSinuosity({omega, 0.0, 1.0}), 1.0 / std::cyl_bessel_j(0.0, omega), 1e-4)
        << omega;
  EXPECT_DOUBLE_EQ(meanderSinuosity({0.0, 0.0, 1.0}), 1.0);
  // Kinoshita's flattening broadens the bends' apexes: a little shorter for the same ω.
  EXPECT_LT(meanderSinuosity({1.5, 0.03, 1.0}), meanderSinuosity({1.5, 0.0, 1.0}));
  EXPECT_GT(meanderSinuosity({1.5, 0.03, 1.0}), 0.98 * meanderSinuosity({1.5, 0.0, 1.0}));
}

TEST(MeanderCurve, ValleyPathLeavesAndArrivesAlongItsTangents) {
  const Vec2 from{0.0, 0.0}, to{1000.0, 300.0};
  const Vec2 leave = normalize(Vec2{1.0, -1.0}), arrive{0.0, 1.0};
  const ValleyPath valley(from, leave, to, arrive);
  EXPECT_EQ(valley.at(0.0), from);
  EXPECT_EQ(valley.at(valley.length()), to);
  EXPECT_LT(distance(valley.tangent(0.0), leave), 1e-9);
  EXPECT_LT(distance(valley.tangent(valley.length()), arrive), 1e-9);
  EXPECT_GT(valley.length(), distance(from, to));
  EXPECT_LT(valley.length(), 1.5 * distance(from, to));
}

TEST(MeanderCurve, WholeWavesStartAndEndOnTheValleyHeadingAlongIt) {
  const ValleyPath valley({0.0, 0.0}, {1.0, 0.0}, {1000.0, 0.0}, {1.0, 0.0});
  const std::vector<MeanderWave> waves(5, MeanderWave{1.5, 0.0, 1.0});
  const CurveSampling sampling;
  const std::vector<Vec2> curve = meanderCurve(valley, waves, sampling);
  ASSERT_GT(curve.size(), 40u);
  EXPECT_EQ(curve.front(), (Vec2{0.0, 0.0}));
  EXPECT_EQ(curve.back(), (Vec2{1000.0, 0.0}));
  EXPECT_LT(turn(curve[1] - curve[0], {1.0, 0.0}), sampling.maxTurn);
  EXPECT_LT(turn(curve.back() - curve[curve.size() - 2], {1.0, 0.0}), sampling.maxTurn);
  EXPECT_NEAR(polylineLength(curve) / 1000.0, 1.0 / std::cyl_bessel_j(0.0, 1.5), 0.03);
  double worstTurn = 0.0, widest = 0.0, farthest = 0.0;
  for (std::size_t i = 1; i < curve.size(); ++i) {
    widest = std::max(widest, distance(curve[i - 1], curve[i]));
    farthest = std::max(farthest, std::abs(curve[i].y));
    if (i + 1 < curve.size())
      worstTurn = std::max(worstTurn, turn(curve[i] - curve[i - 1], curve[i + 1] - curve[i]));
  }
  EXPECT_LE(worstTurn, 30.0 * kDegree);
  EXPECT_LE(widest, sampling.maxStep);
  // The ends are apexes of bends: the channel swings from the axis to about 0.7 wavelengths
  // to one side of it (a belt of 143 m for 200 m waves at ω = 1.5).
  EXPECT_GT(farthest, 125.0);
  EXPECT_LT(farthest, 160.0);
}

TEST(MeanderCurve, WithoutWavesTheCurveIsTheValleyPath) {
  const ValleyPath valley({0.0, 0.0}, {0.0, 1.0}, {800.0, 600.0}, {1.0, 0.0});
  const std::vector<Vec2> curve = meanderCurve(valley, {}, {});
  EXPECT_EQ(curve.front(), valley.at(0.0));
  EXPECT_EQ(curve.back(), valley.at(valley.length()));
  EXPECT_NEAR(polylineLength(curve), valley.length(), 0.01 * valley.length());
  for (std::size_t i = 1; i + 1 < curve.size(); ++i)
    EXPECT_LE(turn(curve[i] - curve[i - 1], curve[i + 1] - curve[i]), 30.0 * kDegree);
}

TEST(MeanderCurve, SameWavesSamePoints) {
  const ValleyPath valley({10.0, 20.0}, {1.0, 0.0}, {900.0, 400.0}, {0.0, 1.0});
  const std::vector<MeanderWave> waves{{1.4, 0.02, 1.1}, {-1.2, 0.0, 0.9}, {1.6, 0.01, 1.0}};
  EXPECT_EQ(meanderCurve(valley, waves, {}), meanderCurve(valley, waves, {}));
}

} // namespace
} // namespace strahler::primitives
