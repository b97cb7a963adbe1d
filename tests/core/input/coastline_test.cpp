#include "input_test_util.h"
#include "ring_validation.h"

#include "strahler/input/coastline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace strahler::input {
namespace {

using base::ErrorCode;
using test_support::collectionJson;
using test_support::failsWith;
using test_support::featureJson;
using test_support::polygonCoordinates;
using test_support::polygonJson;
using test_support::RingPositions;
using test_support::square;

TEST(Coastline, DefaultIslandHasOneIslandWithOneLake) {
  STRAHLER_ASSIGN_OR_ASSERT(auto land, parseCoastline(defaultCoastlineGeoJson()));
  ASSERT_EQ(land.size(), 1u);
  EXPECT_EQ(land[0].holes.size(), 1u);
  EXPECT_EQ(land[0].outer.size(), 720u); // 721 positions minus the closing one
  EXPECT_EQ(land[0].holes[0].size(), 48u);
}

TEST(Coastline, MallorcaParses) {
  STRAHLER_ASSIGN_OR_ASSERT(auto land,
                            parseCoastline(test_support::readTestData("mallorca.geojson")));
  EXPECT_EQ(land.size(), 1u);
}

TEST(Coastline, DropsTheClosingPositionAndRepeatedPositions) {
  const RingPositions ring{{0, 0}, {0, 0}, {1, 0}, {1, 1}, {1, 1}, {1, 1}, {0, 1}, {0, 0}};
  STRAHLER_ASSIGN_OR_ASSERT(auto land, parseCoastline(polygonJson({ring})));
  const geometry::Ring expected{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(land[0].outer, expected);
}

TEST(Coastline, AcceptsEveryPolygonContainerAndAltitudes) {
  const std::string polygon = polygonJson({square(0, 0, 1)});
  const std::string multi = R"({"type":"MultiPolygon","coordinates":[)" +
                            polygonCoordinates({square(0, 0, 1)}) + "," +
                            polygonCoordinates({square(2, 0, 1)}) + "]}";
  const std::string other = polygonJson({square(5, 0, 1)});
  const auto count = [](const std::string& text) -> std::size_t {
    auto land = parseCoastline(text);
    EXPECT_TRUE(land.ok()) << land.error().message;
    return land.ok() ? land.value().size() : 0u;
  };
  EXPECT_EQ(count(polygon), 1u);
  EXPECT_EQ(count(multi), 2u);
  EXPECT_EQ(count(featureJson(multi)), 2u);
  EXPECT_EQ(count(collectionJson({featureJson(other), featureJson(multi)})), 3u);
  auto withAltitude = parseCoastline(
      R"({"type":"Polygon","coordinates":[[[0,0,5],[1,0,5],[1,1,5],[0,1,5],[0,0,5]]]})");
  ASSERT_TRUE(withAltitude.ok()) << withAltitude.error().message;
  EXPECT_EQ(withAltitude.value()[0].outer.size(), 4u);
}

TEST(Coastline, IslandInsideALakeIsAllowed) {
  RingPositions lake = square(2, 2, 6);
  std::reverse(lake.begin(), lake.end());
  const std::string multi = R"({"type":"MultiPolygon","coordinates":[)" +
                            polygonCoordinates({square(0, 0, 10), lake}) + "," +
                            polygonCoordinates({square(4, 4, 1)}) + "]}";
  STRAHLER_ASSIGN_OR_ASSERT(auto land, parseCoastline(multi));
  EXPECT_EQ(land.size(), 2u);
}

TEST(Coastline, NotJson) {
  EXPECT_TRUE(failsWith(parseCoastline("not json"), ErrorCode::kInvalidInput,
                        "coastline: not valid JSON at byte 2"));
}

TEST(Coastline, EmptyObject) {
  EXPECT_TRUE(failsWith(parseCoastline("{}"), ErrorCode::kInvalidInput, "missing \"type\""));
}

TEST(Coastline, EmptyFeatureCollection) {
  EXPECT_TRUE(failsWith(parseCoastline(collectionJson({})), ErrorCode::kInvalidInput,
                        "coastline: FeatureCollection has no features"));
}

TEST(Coastline, PointGeometry) {
  EXPECT_TRUE(failsWith(parseCoastline(R"({"type":"Point","coordinates":[1,2]})"),
                        ErrorCode::kInvalidInput,
                        "coastline: geometry type Point is not a Polygon or MultiPolygon"));
}

TEST(Coastline, LineStringFeature) {
  const std::string polygon = featureJson(polygonJson({square(0, 0, 1)}));
  const std::string line = featureJson(R"({"type":"LineString","coordinates":[[5,5],[6,6]]})");
  EXPECT_TRUE(failsWith(parseCoastline(collectionJson({polygon, polygon, line})),
                        ErrorCode::kInvalidInput,
                        "feature 2: geometry type LineString is not a Polygon or MultiPolygon"));
}

TEST(Coastline, UnclosedRing) {
  EXPECT_TRUE(failsWith(parseCoastline(polygonJson({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}})),
                        ErrorCode::kInvalidInput, "polygon 0, ring 0: ring not closed"));
}

TEST(Coastline, RingWithThreePositions) {
  const std::string multi = R"({"type":"MultiPolygon","coordinates":[)" +
                            polygonCoordinates({square(0, 0, 1)}) + "," +
                            polygonCoordinates({{{5, 5}, {6, 5}, {5, 5}}}) + "]}";
  EXPECT_TRUE(failsWith(parseCoastline(featureJson(multi)), ErrorCode::kInvalidInput,
                        "coastline: feature 0, polygon 1, ring 0: ring has 3 positions, a ring "
                        "needs at least 4"));
}

TEST(Coastline, SelfIntersectingBowTie) {
  EXPECT_TRUE(failsWith(parseCoastline(polygonJson({{{0, 0}, {1, 1}, {1, 0}, {0, 1}, {0, 0}}})),
                        ErrorCode::kInvalidInput,
                        "polygon 0, ring 0: ring intersects itself: segment 0 (positions 0-1) "
                        "touches or crosses segment 2 (positions 2-3)"));
}

TEST(Coastline, SpikeDoublingBack) {
  EXPECT_TRUE(failsWith(parseCoastline(polygonJson({{{0, 0}, {2, 0}, {1, 0}, {1, 1}, {0, 0}}})),
                        ErrorCode::kInvalidInput, "doubles back at position 1"));
}

TEST(Coastline, LongitudeOutOfRange) {
  EXPECT_TRUE(failsWith(parseCoastline(polygonJson({{{0, 0}, {200, 0}, {1, 1}, {0, 0}}})),
                        ErrorCode::kOutOfRange,
                        "polygon 0, ring 0, position 1: longitude 200 is outside [-180, 180]"));
}

TEST(Coastline, LatitudeOutOfRange) {
  EXPECT_TRUE(failsWith(parseCoastline(polygonJson({{{0, 0}, {1, 0}, {1, -95}, {0, 0}}})),
                        ErrorCode::kOutOfRange, "position 2: latitude -95 is outside [-90, 90]"));
}

TEST(Coastline, NumberOverflowingToInfinity) {
  EXPECT_TRUE(failsWith(
      parseCoastline(R"({"type":"Polygon","coordinates":[[[0,0],[1e999,0],[1,1],[0,0]]]})"),
      ErrorCode::kInvalidInput, "number 1e999 at byte"));
  EXPECT_TRUE(failsWith(parseCoastline(R"({"type":"Polygon","coordinates":[[[NaN,0]]]})"),
                        ErrorCode::kInvalidInput, "not valid JSON"));
}

TEST(Coastline, PositionWithOneNumber) {
  EXPECT_TRUE(
      failsWith(parseCoastline(R"({"type":"Polygon","coordinates":[[[0,0],[1],[1,1],[0,0]]]})"),
                ErrorCode::kInvalidInput, "position 1: position has 1 number, a position needs 2"));
}

TEST(Coastline, StringCoordinates) {
  EXPECT_TRUE(failsWith(
      parseCoastline(R"({"type":"Polygon","coordinates":[[[0,0],["1","0"],[1,1],[0,0]]]})"),
      ErrorCode::kInvalidInput, "position 1: coordinate 0 is a string, not a number"));
}

TEST(Coastline, NestingHundredDeep) {
  const std::string deep = std::string(100, '[') + std::string(100, ']');
  EXPECT_TRUE(failsWith(parseCoastline(deep), ErrorCode::kLimitExceeded,
                        "JSON nested deeper than 64 levels (at byte 64)"));
  const std::string nested = R"({"type":"Polygon","coordinates":)" + deep + "}";
  EXPECT_TRUE(failsWith(parseCoastline(nested), ErrorCode::kLimitExceeded,
                        "JSON nested deeper than 64 levels"));
}

TEST(Coastline, TooManyVertices) {
  InputLimits limits;
  limits.maxVertices = 100;
  EXPECT_TRUE(failsWith(parseCoastline(defaultCoastlineGeoJson(), limits),
                        ErrorCode::kLimitExceeded, "more than 100 vertices"));
}

TEST(Coastline, TooManyRings) {
  InputLimits limits;
  limits.maxRings = 1;
  EXPECT_TRUE(failsWith(parseCoastline(defaultCoastlineGeoJson(), limits),
                        ErrorCode::kLimitExceeded,
                        "polygon 0, ring 1: the coastline has more "
                        "than 1 rings"));
}

TEST(Coastline, TooManyBytes) {
  InputLimits limits;
  limits.maxFileBytes = 100;
  EXPECT_TRUE(failsWith(parseCoastline(defaultCoastlineGeoJson(), limits),
                        ErrorCode::kLimitExceeded, "bytes is more than the limit of 100 bytes"));
}

TEST(Coastline, HoleOutsideItsOuterRing) {
  EXPECT_TRUE(failsWith(parseCoastline(polygonJson({square(0, 0, 1), square(3, 3, 1)})),
                        ErrorCode::kInvalidInput,
                        "polygon 0, ring 1: hole is not inside its outer ring (ring 0)"));
}

TEST(Coastline, HoleCrossingItsOuterRing) {
  EXPECT_TRUE(failsWith(parseCoastline(polygonJson({square(0, 0, 2), square(1, 1, 2)})),
                        ErrorCode::kInvalidInput, "polygon 0: rings 0 and 1 touch or cross"));
}

TEST(Coastline, HoleInsideAnotherHole) {
  EXPECT_TRUE(
      failsWith(parseCoastline(polygonJson({square(0, 0, 10), square(1, 1, 8), square(2, 2, 1)})),
                ErrorCode::kInvalidInput, "ring 2: hole lies inside another hole (ring 1)"));
}

TEST(Coastline, OverlappingPolygons) {
  const std::string crossing = collectionJson(
      {featureJson(polygonJson({square(0, 0, 2)})), featureJson(polygonJson({square(1, 1, 2)}))});
  EXPECT_TRUE(failsWith(parseCoastline(crossing), ErrorCode::kInvalidInput,
                        "feature 0, polygon 0 and feature 1, polygon 0 overlap"));
  const std::string nested = collectionJson(
      {featureJson(polygonJson({square(0, 0, 10)})), featureJson(polygonJson({square(1, 1, 2)}))});
  EXPECT_TRUE(failsWith(parseCoastline(nested), ErrorCode::kInvalidInput,
                        "overlap: feature 1, polygon 0 lies inside feature 0, polygon 0"));
}

TEST(Coastline, PolygonsTouchingAtACorner) {
  const std::string multi = R"({"type":"MultiPolygon","coordinates":[)" +
                            polygonCoordinates({square(0, 0, 1)}) + "," +
                            polygonCoordinates({square(1, 1, 1)}) + "]}";
  EXPECT_TRUE(failsWith(parseCoastline(multi), ErrorCode::kInvalidInput,
                        "polygon 0 and polygon 1 overlap"));
}

TEST(Coastline, CrossingTheAntimeridianIsRefused) {
  const std::string multi = R"({"type":"MultiPolygon","coordinates":[)" +
                            polygonCoordinates({square(179, 0, 1)}) + "," +
                            polygonCoordinates({square(-180, 0, 1)}) + "]}";
  EXPECT_TRUE(failsWith(parseCoastline(multi), ErrorCode::kUnsupported, "antimeridian"));
}

TEST(Coastline, FeatureWithNullGeometry) {
  EXPECT_TRUE(failsWith(parseCoastline(R"({"type":"Feature","geometry":null})"),
                        ErrorCode::kInvalidInput, "feature 0: geometry is null"));
}

TEST(Coastline, DuplicateKey) {
  EXPECT_TRUE(failsWith(parseCoastline(R"({"type":"Polygon","type":"Polygon"})"),
                        ErrorCode::kInvalidInput, "duplicate key \"type\" at /type"));
  EXPECT_TRUE(failsWith(
      parseCoastline(R"({"type":"FeatureCollection","features":[{},{"a":[{"b":1,"b":2}]}]})"),
      ErrorCode::kInvalidInput, "duplicate key \"b\" at /features/1/a/0/b"));
}

TEST(Coastline, HundredThousandVerticesValidateInNearLinearTime) {
  // A star-shaped ring whose radius wiggles: checking every pair would take 5·10⁹ segment-pair
  // tests; the grid needs a few per segment. The bound is a count, not seconds: the checker
  // refuses with kLimitExceeded once it would test more pairs than it was given.
  constexpr int kCount = 100'000;
  RingPositions ring;
  for (int i = 0; i < kCount; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / kCount;
    const double radius = 0.5 + 0.05 * std::sin(37.0 * angle) + 0.01 * std::sin(911.0 * angle);
    ring.push_back({10.0 + radius * std::cos(angle), 40.0 + radius * std::sin(angle)});
  }
  ring.push_back(ring.front());
  STRAHLER_ASSIGN_OR_ASSERT(auto land, parseCoastline(polygonJson({ring})));
  EXPECT_EQ(land[0].outer.size(), static_cast<std::size_t>(kCount));

  detail::ParsedPolygon polygon{"polygon 0", {detail::ParsedRing{}}};
  detail::ParsedRing& parsed = polygon.rings[0];
  for (int i = 0; i < kCount; ++i) {
    parsed.vertices.push_back(
        {ring[static_cast<std::size_t>(i)][0], ring[static_cast<std::size_t>(i)][1]});
    parsed.positions.push_back(static_cast<std::uint32_t>(i));
  }
  parsed.closingPosition = kCount;
  constexpr std::uint64_t kLinearBudget = 8u * kCount;
  const base::Status checked = detail::checkTopology({polygon}, kLinearBudget);
  EXPECT_TRUE(checked.ok()) << checked.error().message;
}

} // namespace
} // namespace strahler::input
