#include "strahler/geometry/polygon.h"
#include "strahler/geometry/projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace strahler::geometry {
namespace {

TEST(LocalProjection, RoundTripsWithinMicrodegrees) {
  const LocalProjection projection(2.95, 39.6);
  for (double dlon = -1.0; dlon <= 1.0; dlon += 0.25)
    for (double dlat = -1.0; dlat <= 1.0; dlat += 0.25) {
      const Vec2 ll{2.95 + dlon, 39.6 + dlat};
      const Vec2 back = projection.inverse(projection.forward(ll));
      EXPECT_NEAR(back.x, ll.x, 1e-9);
      EXPECT_NEAR(back.y, ll.y, 1e-9);
    }
}

TEST(LocalProjection, IsEqualArea) {
  // A 1°x1° cell at 45°N has area R² Δλ (sin φ2 − sin φ1) on the sphere.
  const LocalProjection projection(10.5, 45.5);
  const Ring cell{projection.forward({10, 45}), projection.forward({11, 45}),
                  projection.forward({11, 46}), projection.forward({10, 46})};
  // Edges of constant latitude are curved after projection: densify them.
  Ring dense;
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < 100; ++k) {
      const double t = k / 100.0;
      const Vec2 corners[4] = {{10, 45}, {11, 45}, {11, 46}, {10, 46}};
      const Vec2 a = corners[side], b = corners[(side + 1) % 4];
      dense.push_back(projection.forward(a + (b - a) * t));
    }
  constexpr double kDeg = std::numbers::pi / 180.0;
  const double expected =
      kEarthRadius * kEarthRadius * kDeg * (std::sin(46 * kDeg) - std::sin(45 * kDeg));
  EXPECT_NEAR(signedArea(dense) / expected, 1.0, 1e-5);
  EXPECT_GT(signedArea(cell), 0.0);
}

TEST(LocalProjection, CentreMapsToOrigin) {
  const LocalProjection projection(-27.35, 43.72);
  const Vec2 o = projection.forward({-27.35, 43.72});
  EXPECT_NEAR(o.x, 0.0, 1e-9);
  EXPECT_NEAR(o.y, 0.0, 1e-9);
  const Vec2 north = projection.forward({-27.35, 43.73});
  EXPECT_NEAR(north.y, 1111.95, 0.5); // 0.01° of latitude
}

} // namespace
} // namespace strahler::geometry
