#include "strahler/erosion/erosion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace strahler::erosion {
namespace {

constexpr int kSize = 65;
constexpr double kSpacing = 10.0;

/// A cone 400 m high, radius 300 m, on flat ground at 100 m, with a ripple so slopes vary.
std::vector<double> cone() {
  std::vector<double> h(static_cast<std::size_t>(kSize * kSize));
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double r = std::hypot(x - 32.0, y - 32.0) * kSpacing;
      h[static_cast<std::size_t>(y * kSize + x)] = 100.0 +
                                                   std::max(0.0, 400.0 * (1.0 - r / 300.0)) +
                                                   3.0 * std::sin(x * 0.7) * std::cos(y * 0.5);
    }
  return h;
}

double sum(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

TEST(Erosion, ConservesMaterial) {
  const std::vector<double> h = cone();
  auto result = erode(h, kSize, kSize, kSpacing, Params{});
  ASSERT_TRUE(result.ok()) << result.error().message;
  const Layers& l = result.value();
  // The documented tolerance: 1e-9 m per sample.
  EXPECT_NEAR(sum(l.surface()), sum(h), 1e-9 * static_cast<double>(h.size()));
  EXPECT_GT(sum(l.sediment), 1000.0); // Something did happen.
  for (const double s : l.sediment)
    EXPECT_GE(s, 0.0);
}

TEST(Erosion, StabilisationLeavesNoSlopeAboveTheTalus) {
  Params p;
  p.talusDegrees = 30.0;
  p.thermalRate = 2.0;
  auto result = erode(cone(), kSize, kSize, kSpacing, p);
  ASSERT_TRUE(result.ok());
  const Layers& l = result.value();
  EXPECT_TRUE(l.stable);
  EXPECT_LE(talusExcess(l, p.talusDegrees), p.toleranceM);
  // Checked directly: wherever sediment lies, the surface stays within the talus of every
  // neighbour (plus the tolerance).
  const double tanTalus = std::tan(30.0 * std::numbers::pi / 180.0);
  for (int y = 1; y + 1 < kSize; ++y)
    for (int x = 1; x + 1 < kSize; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kSize + x);
      if (l.sediment[i] <= p.toleranceM)
        continue;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const std::size_t n = static_cast<std::size_t>((y + dy) * kSize + x + dx);
          const double d = std::hypot(dx, dy) * kSpacing;
          EXPECT_LE(l.bedrock[i] + l.sediment[i] - l.bedrock[n] - l.sediment[n],
                    tanTalus * d + p.toleranceM)
              << x << "," << y;
        }
    }
}

TEST(Erosion, ConeErodesIntoASmootherCone) {
  const std::vector<double> h = cone();
  auto result = erode(h, kSize, kSize, kSpacing, Params{});
  ASSERT_TRUE(result.ok());
  const std::vector<double> t = result.value().surface();
  const std::size_t peak = static_cast<std::size_t>(32 * kSize + 32);
  EXPECT_LT(t[peak], h[peak] - 1.0);
  // The foot (a ring just outside the cone's base) gets sediment.
  double before = 0.0;
  double after = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double r = std::hypot(x - 32.0, y - 32.0) * kSpacing;
      if (r >= 290.0 && r <= 330.0) {
        before += h[static_cast<std::size_t>(y * kSize + x)];
        after += t[static_cast<std::size_t>(y * kSize + x)];
      }
    }
  EXPECT_GT(after, before + 1.0);
}

TEST(Erosion, FlatGroundStaysFlat) {
  const std::vector<double> h(static_cast<std::size_t>(kSize * kSize), 42.0);
  auto result = erode(h, kSize, kSize, kSpacing, Params{});
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result.value().surface(), h);
  EXPECT_EQ(result.value().bedrock, h);
}

TEST(Erosion, SameBytesWithOneAndTwoThreads) {
  const std::vector<double> h = cone();
  Params one;
  one.threads = 1;
  Params two;
  two.threads = 2;
  Params three;
  three.threads = 3;
  auto a = erode(h, kSize, kSize, kSpacing, one);
  auto b = erode(h, kSize, kSize, kSpacing, two);
  auto c = erode(h, kSize, kSize, kSpacing, three);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  EXPECT_EQ(a.value().bedrock, b.value().bedrock);
  EXPECT_EQ(a.value().sediment, b.value().sediment);
  EXPECT_EQ(a.value().bedrock, c.value().bedrock);
  EXPECT_EQ(a.value().sediment, c.value().sediment);
  EXPECT_EQ(a.value().finalSweeps, b.value().finalSweeps);
}

TEST(Erosion, RejectsBadParameters) {
  const std::vector<double> h = cone();
  Params p;
  p.talusDegrees = 90.0;
  auto r = erode(h, kSize, kSize, kSpacing, p);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, base::ErrorCode::kOutOfRange);
  EXPECT_NE(r.error().message.find("talus angle"), std::string::npos) << r.error().message;

  p = Params{};
  p.talusDegrees = 0.0;
  EXPECT_FALSE(validate(p).ok());

  p = Params{};
  p.iterations = -1;
  r = erode(h, kSize, kSize, kSpacing, p);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("iterations -1"), std::string::npos) << r.error().message;

  p = Params{};
  p.iterations = Params::kMaxIterations + 1;
  EXPECT_FALSE(validate(p).ok());

  p = Params{};
  p.thermalRate = -0.1;
  EXPECT_NE(validate(p).error().message.find("thermal rate"), std::string::npos);

  EXPECT_EQ(erode(h, kSize, kSize - 1, kSpacing, Params{}).error().code,
            base::ErrorCode::kInvalidInput);
  EXPECT_FALSE(erode(h, kSize, kSize, 0.0, Params{}).ok());
  EXPECT_TRUE(validate(Params{}).ok());
}

TEST(Erosion, ZeroIterationsOnlyStabilises) {
  const std::vector<double> h = cone();
  Params p;
  p.iterations = 0;
  auto r = erode(h, kSize, kSize, kSpacing, p);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value().bedrock, h); // No sediment to move, so nothing changes.
  EXPECT_EQ(r.value().finalSweeps, 1);
}

TEST(Erosion, MapsAreInTheUnitRange) {
  const std::vector<double> h = cone();
  const std::vector<double> light = illuminationMap(h, kSize, kSize, kSpacing, 2);
  const std::vector<double> wet = humidityMap(h, kSize, kSize, kSpacing);
  EXPECT_EQ(light, illuminationMap(h, kSize, kSize, kSpacing, 1));
  for (std::size_t i = 0; i < h.size(); ++i) {
    EXPECT_GE(light[i], 0.0);
    EXPECT_LE(light[i], 1.0);
    EXPECT_GE(wet[i], 0.0);
    EXPECT_LE(wet[i], 1.0);
  }
  // The peak sees the whole sky and collects no water; the foot collects the cone's.
  const std::size_t peak = static_cast<std::size_t>(32 * kSize + 32);
  EXPECT_GT(light[peak], 0.99);
  EXPECT_LT(wet[peak], 0.2);
}

TEST(Erosion, ReportsEachRoundAndSweepWithoutChangingTheResult) {
  const std::vector<double> h = cone();
  Params p;
  p.iterations = 5;
  std::vector<Progress> seen;
  Params watched = p;
  watched.onProgress = [&seen](const Progress& progress) {
    seen.push_back(progress);
    return true;
  };
  auto plain = erode(h, kSize, kSize, kSpacing, p);
  auto reported = erode(h, kSize, kSize, kSpacing, watched);
  ASSERT_TRUE(plain.ok() && reported.ok());
  EXPECT_EQ(reported.value().bedrock, plain.value().bedrock);
  EXPECT_EQ(reported.value().sediment, plain.value().sediment);
  ASSERT_EQ(seen.size(), static_cast<std::size_t>(5 + plain.value().finalSweeps));
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(seen[static_cast<std::size_t>(i)].round, i + 1);
    EXPECT_EQ(seen[static_cast<std::size_t>(i)].rounds, 5);
    EXPECT_EQ(seen[static_cast<std::size_t>(i)].finalSweeps, 0);
  }
  EXPECT_EQ(seen.back().finalSweeps, plain.value().finalSweeps);
}

TEST(Erosion, StopsWhenTheProgressCallbackSaysSo) {
  Params p;
  p.iterations = 50;
  int calls = 0;
  p.onProgress = [&calls](const Progress& progress) {
    ++calls;
    return progress.round < 3;
  };
  auto r = erode(cone(), kSize, kSize, kSpacing, p);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "erosion: cancelled");
  EXPECT_EQ(calls, 3);
}

} // namespace
} // namespace strahler::erosion
