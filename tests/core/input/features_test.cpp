// parseFeatures: the artist's vector map, and every way it can be refused.
#include "input_test_util.h"

#include "strahler/input/feature_parser.h"
#include "strahler/input/world_spec.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace strahler::input {
namespace {

using base::ErrorCode;
using test_support::failsWith;

/// A square island 0.5° on a side (lon 10..10.5, lat 40..40.5) with a square lake
/// (lon 10.2..10.3, lat 40.2..40.3).
const WorldSpec& squareIsland() {
  static const WorldSpec spec = [] {
    const std::string coast =
        test_support::collectionJson({test_support::featureJson(test_support::polygonJson(
            {test_support::square(10.0, 40.0, 0.5),
             {{10.2, 40.2}, {10.2, 40.3}, {10.3, 40.3}, {10.3, 40.2}, {10.2, 40.2}}}))});
    auto made = makeWorldSpec("square", coast, Params{});
    EXPECT_TRUE(made.ok());
    return std::move(made).value();
  }();
  return spec;
}

std::string positionsJson(const std::vector<test_support::Position>& points) {
  return test_support::ringJson(points);
}

std::string mountain(double lon, double lat, const std::string& extra = "") {
  return R"({"type":"Feature","properties":{"kind":"mountain")" + extra +
         R"(},"geometry":{"type":"Point","coordinates":[)" + std::to_string(lon) + "," +
         std::to_string(lat) + "]}}";
}

std::string line(const std::string& kind, const std::vector<test_support::Position>& points,
                 const std::string& extra = "") {
  return R"({"type":"Feature","properties":{"kind":")" + kind + "\"" + extra +
         R"(},"geometry":{"type":"LineString","coordinates":)" + positionsJson(points) + "}}";
}

base::Result<Features> parseOn(const WorldSpec& spec, const std::string& geoJson,
                               const InputLimits& limits = {}) {
  return parseFeatures(geoJson, spec.projection, spec.land, spec.params, limits);
}

base::Result<Features> parse(const std::vector<std::string>& features,
                             const InputLimits& limits = {}) {
  return parseOn(squareIsland(), test_support::collectionJson(features), limits);
}

// A river from inland to the east coast.
const std::vector<test_support::Position> kEastRiver{{10.1, 40.25}, {10.4, 40.1}, {10.5, 40.1}};

TEST(Features, TheCorsicaFixtureParses) {
  WorldSources sources;
  sources.coastPath = std::string(STRAHLER_TEST_DATA_DIR) + "/corsica.geojson";
  sources.featuresPath = std::string(STRAHLER_TEST_DATA_DIR) + "/corsica-features.geojson";
  auto spec = loadWorldSpec(sources);
  ASSERT_TRUE(spec.ok()) << spec.error().message;
  const Features& f = spec.value().features;
  ASSERT_EQ(f.mountains.size(), 5u);
  ASSERT_EQ(f.ridges.size(), 1u);
  ASSERT_EQ(f.rivers.size(), 2u);
  EXPECT_EQ(f.mountains[0].lonLat, (geometry::Vec2{8.9456, 42.3797}));
  EXPECT_EQ(f.mountains[0].elevation, 2706.0);
  EXPECT_FALSE(f.mountains[0].radius.has_value());
  EXPECT_EQ(f.mountains[0].position, spec.value().projection.forward({8.9456, 42.3797}));
  EXPECT_EQ(f.ridges[0].line.size(), 5u);
  EXPECT_FALSE(f.ridges[0].elevation.has_value());
  EXPECT_EQ(f.rivers[0].name, "Golo");
  EXPECT_EQ(f.rivers[1].name, "Tavignano");
  ASSERT_EQ(f.rivers[1].lonLat.size(), f.rivers[1].line.size());
  for (std::size_t k = 0; k < f.rivers[1].line.size(); ++k)
    EXPECT_EQ(f.rivers[1].line[k], spec.value().projection.forward(f.rivers[1].lonLat[k]));
}

TEST(Features, ASingleFeatureAndEveryPropertyParse) {
  const std::string text = R"({"type":"Feature","id":7,"properties":{"kind":"mountain",)"
                           R"("elevation":1200.5,"radius":3000},"geometry":{"type":"Point",)"
                           R"("coordinates":[10.25,40.1]}})";
  auto parsed = parseOn(squareIsland(), text);
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  ASSERT_EQ(parsed.value().mountains.size(), 1u);
  EXPECT_EQ(parsed.value().mountains[0].elevation, 1200.5);
  EXPECT_EQ(parsed.value().mountains[0].radius, 3000.0);
  auto lines = parse({line("ridge", {{10.05, 40.4}, {10.45, 40.45}}, R"(,"elevation":900)"),
                      line("river", kEastRiver, R"(,"name":"Aa")")});
  ASSERT_TRUE(lines.ok()) << lines.error().message;
  EXPECT_EQ(lines.value().ridges[0].elevation, 900.0);
  EXPECT_EQ(lines.value().rivers[0].name, "Aa");
}

TEST(Features, AnEmptyCollectionIsNoFeatures) {
  auto parsed = parse({});
  ASSERT_TRUE(parsed.ok());
  EXPECT_TRUE(parsed.value().empty());
}

TEST(Features, RefusesBadStructure) {
  EXPECT_TRUE(failsWith(parseOn(squareIsland(), "[1]"), ErrorCode::kInvalidInput,
                        "features: expected a GeoJSON object"));
  EXPECT_TRUE(failsWith(parseOn(squareIsland(), R"({"type":"Point","coordinates":[10,40]})"),
                        ErrorCode::kInvalidInput, "is not a FeatureCollection or Feature"));
  EXPECT_TRUE(failsWith(parseOn(squareIsland(), "{\"type\":"), ErrorCode::kInvalidInput,
                        "features: not valid JSON"));
  EXPECT_TRUE(failsWith(parse({mountain(10.1, 40.1), "3"}), ErrorCode::kInvalidInput,
                        "features: feature 1: not a GeoJSON Feature"));
  EXPECT_TRUE(failsWith(parse({R"({"type":"Feature","properties":null,"geometry":null})"}),
                        ErrorCode::kInvalidInput, "feature 0: \"properties\" must be an object"));
  EXPECT_TRUE(
      failsWith(parse({R"({"type":"Feature","properties":{"kind":"ridge"},"geometry":null})"}),
                ErrorCode::kInvalidInput, "feature 0 (ridge): missing geometry"));
}

TEST(Features, RefusesAnUnknownOrMissingKind) {
  EXPECT_TRUE(failsWith(parse({mountain(10.1, 40.1), line("volcano", kEastRiver)}),
                        ErrorCode::kInvalidInput,
                        "features: feature 1: unknown kind \"volcano\"; expected \"mountain\", "
                        "\"ridge\" or \"river\""));
  EXPECT_TRUE(failsWith(
      parse(
          {R"({"type":"Feature","properties":{},"geometry":{"type":"Point","coordinates":[10,40]}})"}),
      ErrorCode::kInvalidInput, "feature 0: no \"kind\" property"));
  EXPECT_TRUE(failsWith(
      parse(
          {R"({"type":"Feature","properties":{"kind":3},"geometry":{"type":"Point","coordinates":[10,40]}})"}),
      ErrorCode::kInvalidInput, "feature 0: unknown kind a number"));
}

TEST(Features, RefusesAnUnknownProperty) {
  EXPECT_TRUE(failsWith(parse({mountain(10.1, 40.1, R"(,"id":"m1")")}), ErrorCode::kInvalidInput,
                        "feature 0 (mountain): unknown property \"id\"; a mountain takes "
                        "\"elevation\" and \"radius\" besides \"kind\""));
  EXPECT_TRUE(failsWith(parse({line("river", kEastRiver, R"(,"elevation":10)")}),
                        ErrorCode::kInvalidInput,
                        "feature 0 (river): unknown property \"elevation\"; a river takes "
                        "\"name\""));
  EXPECT_TRUE(failsWith(parse({line("ridge", kEastRiver, R"(,"radius":10)")}),
                        ErrorCode::kInvalidInput, "(ridge): unknown property \"radius\""));
  EXPECT_TRUE(failsWith(parse({mountain(10.1, 40.1, R"(,"name":"Cinto")")}),
                        ErrorCode::kInvalidInput, "(mountain): unknown property \"name\""));
}

TEST(Features, RefusesAWrongGeometryType) {
  EXPECT_TRUE(failsWith(parse({line("mountain", kEastRiver)}), ErrorCode::kInvalidInput,
                        "feature 0 (mountain): geometry type LineString is not a Point"));
  const std::string pointRiver =
      R"({"type":"Feature","properties":{"kind":"river"},"geometry":{"type":"Point","coordinates":[10.1,40.1]}})";
  EXPECT_TRUE(failsWith(parse({pointRiver}), ErrorCode::kInvalidInput,
                        "feature 0 (river): geometry type Point is not a LineString"));
  EXPECT_TRUE(failsWith(parse({line("ridge", {{10.1, 40.1}})}), ErrorCode::kInvalidInput,
                        "feature 0 (ridge): a LineString needs an array of at least 2 positions"));
}

TEST(Features, RefusesBadNumbers) {
  EXPECT_TRUE(failsWith(
      parse(
          {R"({"type":"Feature","properties":{"kind":"mountain"},"geometry":{"type":"Point","coordinates":[1e999,40]}})"}),
      ErrorCode::kInvalidInput, "features: number 1e999 at byte"));
  EXPECT_TRUE(failsWith(parse({line("river", {{10.1, 40.1}, {200.0, 40.1}})}),
                        ErrorCode::kOutOfRange,
                        "feature 0 (river): point 1: longitude 200 is outside [-180, 180]"));
  EXPECT_TRUE(failsWith(parse({mountain(10.1, 40.1, R"(,"elevation":-5)")}), ErrorCode::kOutOfRange,
                        "feature 0 (mountain): \"elevation\" -5 m is outside (0, 10000]"));
  EXPECT_TRUE(failsWith(parse({mountain(10.1, 40.1, R"(,"radius":0)")}), ErrorCode::kOutOfRange,
                        "\"radius\" 0 m is outside (0, "));
  EXPECT_TRUE(failsWith(parse({mountain(10.1, 40.1, R"(,"elevation":"high")")}),
                        ErrorCode::kInvalidInput,
                        "\"elevation\" must be a number (metres), got a "
                        "string"));
  EXPECT_TRUE(failsWith(parse({line("river", kEastRiver, R"(,"name":5)")}),
                        ErrorCode::kInvalidInput, "\"name\" must be a string, got a number"));
}

TEST(Features, RefusesRepeatedPoints) {
  EXPECT_TRUE(failsWith(parse({line("river", {{10.1, 40.1}, {10.1, 40.1}, {10.5, 40.1}})}),
                        ErrorCode::kInvalidInput,
                        "feature 0 (river): point 1 at (10.10000, 40.10000) repeats point 0"));
}

TEST(Features, RefusesTooManyFeaturesOrPoints) {
  InputLimits limits;
  limits.maxFeatures = 2;
  EXPECT_TRUE(
      failsWith(parse({mountain(10.1, 40.1), mountain(10.1, 40.2), mountain(10.1, 40.3)}, limits),
                ErrorCode::kLimitExceeded, "feature 2: more than 2 features (limit maxFeatures)"));
  limits = InputLimits{};
  limits.maxFeatureVertices = 4;
  EXPECT_TRUE(failsWith(parse({mountain(10.1, 40.1), line("river", kEastRiver),
                               line("ridge", {{10.05, 40.4}, {10.45, 40.45}})},
                              limits),
                        ErrorCode::kLimitExceeded,
                        "feature 2 (ridge): point 0: more than 4 points in all features (limit "
                        "maxFeatureVertices)"));
}

TEST(Features, RefusesAMountainInTheSeaOrALake) {
  EXPECT_TRUE(failsWith(parse({mountain(10.1, 40.1), mountain(10.7, 40.2)}),
                        ErrorCode::kInvalidInput,
                        "features: feature 1 (mountain): the mountain at (10.70000, 40.20000) "
                        "lies off the land (in the sea or a lake)"));
  EXPECT_TRUE(failsWith(parse({mountain(10.25, 40.25)}), ErrorCode::kInvalidInput,
                        "feature 0 (mountain): the mountain at (10.25000, 40.25000) lies off"));
}

TEST(Features, ARiverMayEndOnALakeShore) {
  auto parsed = parse({line("river", {{10.05, 40.25}, {10.2, 40.25}})});
  EXPECT_TRUE(parsed.ok()) << parsed.error().message;
  // Within the mouth tolerance (1.5 edge lengths) of the shore is enough.
  auto near = parse({line("river", {{10.05, 40.25}, {10.19, 40.25}})});
  EXPECT_TRUE(near.ok()) << near.error().message;
}

TEST(Features, RefusesARiverThatEndsInlandOrInTheWater) {
  EXPECT_TRUE(failsWith(parse({line("river", {{10.05, 40.1}, {10.15, 40.1}}, R"(,"name":"Dry")")}),
                        ErrorCode::kInvalidInput,
                        "features: feature 0 (river \"Dry\"): ends inland without a lake: its last "
                        "point (10.15000, 40.10000) is more than 1.50 km from the coast and every "
                        "lake shore"));
  EXPECT_TRUE(failsWith(parse({line("river", {{10.4, 40.25}, {10.6, 40.25}})}),
                        ErrorCode::kInvalidInput,
                        "feature 0 (river): its last point (10.60000, 40.25000) is more than "
                        "1.50 km out in the water"));
}

TEST(Features, RefusesARiverThatLeavesTheLand) {
  EXPECT_TRUE(failsWith(parse({line("river", {{10.6, 40.25}, {10.5, 40.25}})}),
                        ErrorCode::kInvalidInput,
                        "feature 0 (river): its source (point 0) (10.60000, 40.25000) is off the "
                        "land"));
  EXPECT_TRUE(
      failsWith(parse({line("river", {{10.4, 40.05}, {10.6, 40.1}, {10.45, 40.2}, {10.5, 40.3}})}),
                ErrorCode::kInvalidInput, "feature 0 (river): leaves the land at (10.50"));
  // Across the lake.
  EXPECT_TRUE(failsWith(parse({line("river", {{10.1, 40.25}, {10.4, 40.25}, {10.5, 40.25}})}),
                        ErrorCode::kInvalidInput, "leaves the land at (10.2"));
  // Out to sea and back through the mouth's zone, the far part away from the shore.
  EXPECT_TRUE(failsWith(
      parse(
          {line("river",
                {{10.3, 40.24}, {10.51, 40.245}, {10.6, 40.25}, {10.51, 40.255}, {10.5, 40.25}})}),
      ErrorCode::kInvalidInput,
      "feature 0 (river): leaves the land at point 2 (10.60000, 40.25000)"));
  // A little over the coast, within 0.25 edge lengths, is allowed.
  auto grazing =
      parse({line("river", {{10.4, 40.05}, {10.501, 40.1}, {10.45, 40.2}, {10.5, 40.3}})});
  EXPECT_TRUE(grazing.ok()) << grazing.error().message;
}

TEST(Features, RefusesARiverThatCrossesItself) {
  EXPECT_TRUE(failsWith(
      parse({line("river",
                  {{10.1, 40.10}, {10.3, 40.15}, {10.3, 40.10}, {10.15, 40.18}, {10.5, 40.05}})}),
      ErrorCode::kInvalidInput, "feature 0 (river): crosses itself at (10.2"));
  EXPECT_TRUE(
      failsWith(parse({line("river", {{10.1, 40.1}, {10.3, 40.1}, {10.2, 40.1}, {10.5, 40.05}})}),
                ErrorCode::kInvalidInput,
                "feature 0 (river): doubles back on itself at point 1 (10.30000, "
                "40.10000)"));
}

TEST(Features, RefusesARiverThatCrossesAnotherRiverOrARidge) {
  const auto a = line("river", {{10.1, 40.4}, {10.5, 40.4}});
  const auto b = line("river", {{10.4, 40.45}, {10.4, 40.35}, {10.5, 40.35}});
  EXPECT_TRUE(failsWith(parse({a, b}), ErrorCode::kInvalidInput,
                        "features: feature 0 (river): crosses feature 1 (river) at (10.4"));
  EXPECT_TRUE(failsWith(parse({line("ridge", {{10.35, 40.05}, {10.35, 40.45}}), a}),
                        ErrorCode::kInvalidInput,
                        "features: feature 1 (river): crosses feature 0 (ridge) at (10.35"));
  // Ridges may cross ridges.
  auto ridges = parse({line("ridge", {{10.35, 40.05}, {10.35, 40.45}}),
                       line("ridge", {{10.05, 40.1}, {10.45, 40.15}})});
  EXPECT_TRUE(ridges.ok()) << ridges.error().message;
}

TEST(Features, RefusesMouthsCloserThanTheMouthSpacing) {
  const auto a = line("river", {{10.3, 40.1}, {10.5, 40.25}});
  EXPECT_TRUE(failsWith(parse({a, line("river", {{10.3, 40.4}, {10.5, 40.26}})}),
                        ErrorCode::kInvalidInput,
                        "features: feature 1 (river): its mouth (10.50000, 40.26000) is 1.11 km "
                        "from the mouth of feature 0 (river) at (10.50000, 40.25000); mouths must "
                        "be at least mouthSpacing = 3.00 km apart"));
  auto spaced = parse({a, line("river", {{10.3, 40.4}, {10.5, 40.3}})});
  EXPECT_TRUE(spaced.ok()) << spaced.error().message;
}

TEST(Features, ErrorsFromAFileNameThePath) {
  const auto dir = test_support::tempDir();
  WorldSources sources;
  sources.featuresPath = (dir / "missing.geojson").string();
  EXPECT_TRUE(failsWith(loadWorldSpec(sources), ErrorCode::kNotFound,
                        "features file '" + sources.featuresPath + "': file not found"));
  sources.featuresPath = test_support::writeFile(
      dir / "bad.geojson", test_support::collectionJson({mountain(170.0, 0.0)}));
  EXPECT_TRUE(failsWith(loadWorldSpec(sources), ErrorCode::kInvalidInput,
                        sources.featuresPath + ": features: feature 0 (mountain): the mountain"));
}

} // namespace
} // namespace strahler::input
