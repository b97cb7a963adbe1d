// Web Mercator (web_mercator.h): the map's corners and centre, OpenStreetMap's formula, the
// clamp at the map's edge, and the inverse.
#include "strahler/geometry/web_mercator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace strahler::geometry {
namespace {

TEST(WebMercator, TheMapIsTheUnitSquareNorthWestFirst) {
  const Vec2 centre = webMercatorUnit({0.0, 0.0});
  EXPECT_DOUBLE_EQ(centre.x, 0.5);
  EXPECT_DOUBLE_EQ(centre.y, 0.5);
  const Vec2 northWest = webMercatorUnit({-180.0, kMaxWebMercatorLatitude});
  EXPECT_DOUBLE_EQ(northWest.x, 0.0);
  EXPECT_NEAR(northWest.y, 0.0, 1e-12);
  const Vec2 southEast = webMercatorUnit({180.0, -kMaxWebMercatorLatitude});
  EXPECT_DOUBLE_EQ(southEast.x, 1.0);
  EXPECT_NEAR(southEast.y, 1.0, 1e-12);
}

TEST(WebMercator, AgreesWithTheSlippyMapFormula) {
  // OpenStreetMap's tile numbers: y = (1 − ln(tan φ + sec φ) / π) / 2 · 2^z.
  for (double lat = -80.0; lat <= 80.0; lat += 10.0) {
    const double phi = lat * std::numbers::pi / 180.0;
    const double y = (1.0 - std::log(std::tan(phi) + 1.0 / std::cos(phi)) / std::numbers::pi) / 2.0;
    EXPECT_NEAR(webMercatorUnit({2.65, lat}).y, y, 1e-12) << lat;
  }
  EXPECT_DOUBLE_EQ(webMercatorUnit({2.65, 39.57}).x, (2.65 + 180.0) / 360.0);
}

TEST(WebMercator, LatitudesBeyondTheMapAreClampedToItsEdge) {
  EXPECT_EQ(webMercatorUnit({10.0, 89.0}).y, webMercatorUnit({10.0, kMaxWebMercatorLatitude}).y);
  EXPECT_EQ(webMercatorUnit({10.0, -90.0}).y, webMercatorUnit({10.0, -kMaxWebMercatorLatitude}).y);
}

TEST(WebMercator, TheInverseReturnsThePlace) {
  for (double lon = -179.0; lon <= 179.0; lon += 17.0)
    for (double lat = -85.0; lat <= 85.0; lat += 8.5) {
      const Vec2 back = lonLatOfWebMercatorUnit(webMercatorUnit({lon, lat}));
      EXPECT_NEAR(back.x, lon, 1e-9);
      EXPECT_NEAR(back.y, lat, 1e-9);
      EXPECT_NEAR(latitudeOfNorthing(mercatorNorthing(lat)), lat, 1e-12);
    }
}

} // namespace
} // namespace strahler::geometry
