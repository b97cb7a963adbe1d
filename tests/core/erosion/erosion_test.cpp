#include "strahler/erosion/erosion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
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

/// A ramp `width` × `rows` falling 2 m per 10 m sample eastwards (tan β = 0.2), level north to
/// south: h = 100 − 2x.
std::vector<double> ramp(int width, int rows) {
  std::vector<double> h;
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < width; ++x)
      h.push_back(100.0 - 2.0 * x);
  return h;
}

/// One round of one process, and a talus so steep (89.9°: 5.7 km per 10 m) that the
/// stabilisation moves nothing: what is left is that process's own step.
Params oneRoundOf(bool thermal, bool hydraulic) {
  Params p;
  p.iterations = 1;
  p.thermal = thermal;
  p.hydraulic = hydraulic;
  p.talusDegrees = 89.9;
  return p;
}

TEST(Erosion, ThermalAloneWeathersRateTimesSlopeTimesIlluminationInPlace) {
  // Seed §1.3.1 by hand: every cell turns T·tanβ·I of bedrock into sediment where it stands
  // (T = thermalRate = 1 m). tan β by central differences with the edges repeated: 0.2 inside,
  // 0.1 in the first and last columns (half a step each way). I is the seed's illumination of
  // the input (illuminationMap, a map of its own); nothing moves, so the surface is unchanged.
  constexpr int kWidth = 8, kRows = 5;
  const std::vector<double> h = ramp(kWidth, kRows);
  auto r = erode(h, kWidth, kRows, kSpacing, oneRoundOf(true, false));
  ASSERT_TRUE(r.ok()) << r.error().message;
  const Layers& l = r.value();
  const std::vector<double> light = illuminationMap(h, kWidth, kRows, kSpacing, 1);
  int shaded = 0;
  for (int y = 0; y < kRows; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kWidth + x);
      const double tanBeta = (x == 0 || x == kWidth - 1) ? 0.1 : 0.2;
      const double weathered = 1.0 * tanBeta * light[i];
      EXPECT_NEAR(l.sediment[i], weathered, 1e-12) << x << "," << y;
      EXPECT_NEAR(l.bedrock[i], h[i] - weathered, 1e-12) << x << "," << y;
      EXPECT_NEAR(l.bedrock[i] + l.sediment[i], h[i], 1e-12) << x << "," << y;
      shaded += light[i] < 0.999 ? 1 : 0;
    }
  EXPECT_GT(shaded, 0) << "the ramp's own slope hides part of the sky";
  EXPECT_GT(l.sediment[static_cast<std::size_t>(2 * kWidth + 3)], 0.1);
}

TEST(Erosion, HydraulicAloneCarriesTheHandWorkedLoadsOneCellDownhill) {
  // Seed §1.3.2 on a two-row ramp, by hand. Humidity: every cell starts with 1 m³ of water and
  // passes it to its lower neighbours (east 0.2 m/m, south- or north-east 0.2/√2), whose
  // shares sum to 1, so column x collects x + 1 and H(x) = ln(x + 1) / ln 8. tan β: 0.2 inside,
  // 0.1 at the ends. Each cell's load Qa = min(T·H·tanβ, half the 2 m drop) with T = 2 goes to
  // its steepest-descent neighbour, the one east; the last column has none. Sediment is zero
  // before, so the load comes out of the bedrock.
  constexpr int kWidth = 8, kRows = 2;
  const std::vector<double> h = ramp(kWidth, kRows);
  auto r = erode(h, kWidth, kRows, kSpacing, oneRoundOf(false, true));
  ASSERT_TRUE(r.ok()) << r.error().message;
  const Layers& l = r.value();
  const auto load = [](int x) {
    if (x == kWidth - 1)
      return 0.0; // no lower neighbour
    const double tanBeta = x == 0 ? 0.1 : 0.2;
    return std::min(2.0 * std::log(x + 1.0) / std::log(8.0) * tanBeta, 1.0);
  };
  EXPECT_NEAR(load(1), 0.4 / 3.0, 1e-15);       // ln 2 / ln 8 = 1/3
  EXPECT_NEAR(load(3), 0.4 * 2.0 / 3.0, 1e-15); // ln 4 / ln 8 = 2/3
  for (int y = 0; y < kRows; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kWidth + x);
      EXPECT_NEAR(l.bedrock[i], h[i] - load(x), 1e-9) << x << "," << y;
      EXPECT_NEAR(l.sediment[i], x == 0 ? 0.0 : load(x - 1), 1e-9) << x << "," << y;
    }
}

TEST(Erosion, NoProcessChangesNothingAndEachAloneDiffersFromBoth) {
  const std::vector<double> h = cone();
  Params none = oneRoundOf(false, false);
  none.talusDegrees = 45.0;
  auto still = erode(h, kSize, kSize, kSpacing, none);
  ASSERT_TRUE(still.ok());
  EXPECT_EQ(still.value().bedrock, h);
  double sediment[3] = {};
  int k = 0;
  for (const auto& [thermal, hydraulic] : {std::pair{true, false}, {false, true}, {true, true}}) {
    Params p;
    p.iterations = 5;
    p.thermal = thermal;
    p.hydraulic = hydraulic;
    auto r = erode(h, kSize, kSize, kSpacing, p);
    ASSERT_TRUE(r.ok());
    sediment[k++] = sum(r.value().sediment);
  }
  EXPECT_GT(sediment[0], 1.0);
  EXPECT_GT(sediment[1], 1.0);
  EXPECT_NE(sediment[0], sediment[2]);
  EXPECT_NE(sediment[1], sediment[2]);
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
