#include "input_test_util.h"

#include "strahler/input/coastline.h"
#include "strahler/input/world_spec.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

namespace strahler::input {
namespace {

using base::ErrorCode;
using test_support::failsWith;
using test_support::writeFile;

std::string dataPath(const std::string& name) {
  return std::string(STRAHLER_TEST_DATA_DIR) + "/" + name;
}

std::uint64_t bits(double v) {
  return std::bit_cast<std::uint64_t>(v);
}

/// Every vertex of every ring, in order.
std::vector<geometry::Vec2> allVertices(const geometry::MultiPolygon& land) {
  std::vector<geometry::Vec2> out;
  for (const geometry::Polygon& p : land) {
    out.insert(out.end(), p.outer.begin(), p.outer.end());
    for (const geometry::Ring& h : p.holes)
      out.insert(out.end(), h.begin(), h.end());
  }
  return out;
}

TEST(WorldSpec, DefaultIslandIsAboutAThousandSquareKilometresWithOneLake) {
  STRAHLER_ASSIGN_OR_ASSERT(auto spec, loadWorldSpec({}));
  const WorldSpec& w = spec;
  EXPECT_EQ(w.name, "default");
  EXPECT_NEAR(w.areaKm2(), 1000.0, 100.0);
  ASSERT_EQ(w.land.size(), 1u);
  ASSERT_EQ(w.land[0].holes.size(), 1u);
  EXPECT_GT(geometry::signedArea(w.land[0].outer), 0.0);    // outer counter-clockwise
  EXPECT_LT(geometry::signedArea(w.land[0].holes[0]), 0.0); // lake clockwise
  EXPECT_EQ(w.params, Params{});
  EXPECT_TRUE(w.mouths.empty());
}

TEST(WorldSpec, ProjectionIsCentredOnTheLandCentroid) {
  STRAHLER_ASSIGN_OR_ASSERT(auto spec, loadWorldSpec({}));
  const geometry::Vec2 c = geometry::centroid(spec.land);
  EXPECT_LT(geometry::length(c), 10.0) << c.x << ", " << c.y; // metres from the origin
}

TEST(WorldSpec, MallorcaAreaMatchesItsKnownArea) {
  WorldSources sources;
  sources.coastPath = dataPath("mallorca.geojson");
  STRAHLER_ASSIGN_OR_ASSERT(auto spec, loadWorldSpec(sources));
  EXPECT_EQ(spec.name, "mallorca");
  EXPECT_NEAR(spec.areaKm2(), 3640.0, 0.05 * 3640.0);
}

TEST(WorldSpec, ProjectionRoundTripIsWithinAMicrodegree) {
  WorldSources sources;
  sources.coastPath = dataPath("corsica.geojson");
  STRAHLER_ASSIGN_OR_ASSERT(auto spec, loadWorldSpec(sources));
  const WorldSpec& w = spec;
  for (const geometry::Vec2& lonLat : allVertices(w.landLonLat)) {
    const geometry::Vec2 back = w.projection.inverse(w.projection.forward(lonLat));
    ASSERT_NEAR(back.x, lonLat.x, 1e-6);
    ASSERT_NEAR(back.y, lonLat.y, 1e-6);
  }
}

TEST(WorldSpec, SameInputsGiveTheSameSpecBitForBit) {
  WorldSources sources;
  sources.coastPath = dataPath("corsica.geojson");
  auto a = loadWorldSpec(sources);
  auto b = loadWorldSpec(sources);
  STRAHLER_ASSERT_OK(a);
  STRAHLER_ASSERT_OK(b);
  const auto va = allVertices(a.value().land);
  const auto vb = allVertices(b.value().land);
  ASSERT_EQ(va.size(), vb.size());
  for (std::size_t i = 0; i < va.size(); ++i) {
    ASSERT_EQ(bits(va[i].x), bits(vb[i].x)) << i;
    ASSERT_EQ(bits(va[i].y), bits(vb[i].y)) << i;
  }
  EXPECT_EQ(bits(a.value().projection.center().x), bits(b.value().projection.center().x));
  EXPECT_EQ(bits(a.value().projection.center().y), bits(b.value().projection.center().y));
}

TEST(WorldSpec, TooMuchArea) {
  InputLimits limits;
  limits.maxAreaKm2 = 100.0;
  auto spec = makeWorldSpec("small", defaultCoastlineGeoJson(), Params{}, limits);
  EXPECT_TRUE(failsWith(spec, ErrorCode::kLimitExceeded, "coastline: land area 10"));
  EXPECT_TRUE(failsWith(spec, ErrorCode::kLimitExceeded, "km² is more than the limit of 100.0"));
}

TEST(WorldSpec, TooLargeExtent) {
  InputLimits limits;
  limits.maxExtentKm = 10.0;
  EXPECT_TRUE(failsWith(makeWorldSpec("wide", defaultCoastlineGeoJson(), Params{}, limits),
                        ErrorCode::kLimitExceeded, "more than the limit of 10.0 km on a side"));
}

TEST(WorldSpec, MakeWorldSpecValidatesParams) {
  Params params;
  params.kappa = -1.0;
  EXPECT_TRUE(failsWith(makeWorldSpec("x", defaultCoastlineGeoJson(), params),
                        ErrorCode::kOutOfRange, "'kappa'"));
}

TEST(WorldSpec, MissingCoastlineFile) {
  WorldSources sources;
  sources.coastPath = (test_support::tempDir() / "absent.geojson").string();
  EXPECT_TRUE(failsWith(loadWorldSpec(sources), ErrorCode::kNotFound,
                        "coastline file '" + sources.coastPath + "': file not found"));
}

TEST(WorldSpec, MissingParamsFile) {
  WorldSources sources;
  sources.paramsPath = (test_support::tempDir() / "absent.json").string();
  EXPECT_TRUE(failsWith(loadWorldSpec(sources), ErrorCode::kNotFound, sources.paramsPath));
}

TEST(WorldSpec, MissingMouthsFile) {
  WorldSources sources;
  sources.mouthsPath = (test_support::tempDir() / "absent.geojson").string();
  EXPECT_TRUE(failsWith(loadWorldSpec(sources), ErrorCode::kNotFound, sources.mouthsPath));
}

TEST(WorldSpec, FileTooLarge) {
  InputLimits limits;
  limits.maxFileBytes = 1000;
  WorldSources sources;
  sources.coastPath = dataPath("mallorca.geojson");
  EXPECT_TRUE(failsWith(loadWorldSpec(sources, limits), ErrorCode::kLimitExceeded,
                        "more than the limit of 1000 bytes"));
}

TEST(WorldSpec, ErrorsInsideAFileNameTheFile) {
  const auto dir = test_support::tempDir();
  WorldSources sources;
  sources.paramsPath = writeFile(dir / "params.json", R"({"sigmaa": 900})");
  EXPECT_TRUE(failsWith(loadWorldSpec(sources), ErrorCode::kInvalidInput,
                        sources.paramsPath + ": params: unknown key 'sigmaa'"));
  sources = {};
  sources.coastPath = writeFile(dir / "coast.geojson", "[");
  EXPECT_TRUE(failsWith(loadWorldSpec(sources), ErrorCode::kInvalidInput,
                        sources.coastPath + ": coastline: not valid JSON"));
}

TEST(WorldSpec, SeedOverrideWins) {
  const auto dir = test_support::tempDir();
  WorldSources sources;
  sources.paramsPath = writeFile(dir / "params.json", R"({"seed": 5})");
  EXPECT_EQ(strahler::test_support::valueOf(loadWorldSpec(sources)).params.seed, 5u);
  sources.seed = 99;
  EXPECT_EQ(strahler::test_support::valueOf(loadWorldSpec(sources)).params.seed, 99u);
}

constexpr const char* kMouths = R"({"type": "FeatureCollection", "features": [
  {"type": "Feature", "properties": {"priority": 3},
   "geometry": {"type": "Point", "coordinates": [-27.03, 43.72]}},
  {"type": "Feature", "properties": null,
   "geometry": {"type": "MultiPoint", "coordinates": [[-27.7, 43.7], [-27.4, 43.84, 0]]}}]})";

TEST(WorldSpec, MouthsAreReadWithPrioritiesAndProjected) {
  WorldSources sources;
  sources.mouthsPath = writeFile(test_support::tempDir() / "mouths.geojson", kMouths);
  STRAHLER_ASSIGN_OR_ASSERT(auto spec, loadWorldSpec(sources));
  const WorldSpec& w = spec;
  ASSERT_EQ(w.mouths.size(), 3u);
  EXPECT_EQ(w.mouths[0].priority, 3);
  EXPECT_EQ(w.mouths[1].priority, 1);
  EXPECT_EQ(w.mouths[2].priority, 1);
  EXPECT_EQ(w.mouths[2].lonLat, (geometry::Vec2{-27.4, 43.84}));
  for (const UserMouth& m : w.mouths)
    EXPECT_EQ(m.position, w.projection.forward(m.lonLat));
}

TEST(WorldSpec, MouthWithNonPointGeometry) {
  WorldSources sources;
  sources.mouthsPath =
      writeFile(test_support::tempDir() / "mouths.geojson",
                R"({"type": "Feature", "geometry": {"type": "Polygon", "coordinates": []}})");
  EXPECT_TRUE(failsWith(loadWorldSpec(sources), ErrorCode::kInvalidInput,
                        "mouths: feature 0: geometry type Polygon is not a Point or MultiPoint"));
}

TEST(WorldSpec, MouthWithPriorityZero) {
  WorldSources sources;
  sources.mouthsPath = writeFile(test_support::tempDir() / "mouths.geojson",
                                 R"({"type": "FeatureCollection", "features": [
      {"type": "Feature", "properties": {"priority": 2},
       "geometry": {"type": "Point", "coordinates": [-27.03, 43.72]}},
      {"type": "Feature", "properties": {"priority": 0},
       "geometry": {"type": "Point", "coordinates": [-27.03, 43.72]}}]})");
  EXPECT_TRUE(failsWith(loadWorldSpec(sources), ErrorCode::kOutOfRange,
                        "mouths: feature 1: priority 0 must be an integer >= 1"));
}

TEST(WorldSpec, TooManyMouths) {
  InputLimits limits;
  limits.maxMouths = 2;
  WorldSources sources;
  sources.mouthsPath = writeFile(test_support::tempDir() / "mouths.geojson", kMouths);
  EXPECT_TRUE(failsWith(loadWorldSpec(sources, limits), ErrorCode::kLimitExceeded,
                        "mouths: feature 1: point 1: more than 2 mouths"));
}

/// A 2x1 PNG, black on the west and white on the east.
void writeHalfAndHalf(const std::filesystem::path& path) {
  const image::RgbImage image{2, 1, {0, 0, 0, 255, 255, 255}};
  STRAHLER_ASSERT_OK(image::writePng(path.string(), image));
}

TEST(WorldSpec, ConstraintImagesAreLoadedRelativeToTheParamsFile) {
  const auto dir = test_support::tempDir();
  std::filesystem::create_directories(dir / "maps");
  writeHalfAndHalf(dir / "maps" / "m.png");
  WorldSources sources;
  sources.paramsPath = writeFile(dir / "params.json", R"({"constraints": [
      {"kind": "mountainousness", "image": "maps/m.png", "bounds": [-28, 43, -26, 44]}]})");
  STRAHLER_ASSIGN_OR_ASSERT(auto spec, loadWorldSpec(sources));
  const WorldSpec& w = spec;
  ASSERT_EQ(w.constraints.size(), 1u);
  const auto at = [&](double lon, double lat) {
    return w.constraintAt(ConstraintKind::kMountainousness, w.projection.forward({lon, lat}));
  };
  ASSERT_TRUE(at(-27.9, 43.5).has_value());
  EXPECT_NEAR(*at(-27.9, 43.5), 0.0, 1e-6);  // west quarter: the black pixel
  EXPECT_NEAR(*at(-26.1, 43.5), 1.0, 1e-6);  // east quarter: the white pixel
  EXPECT_NEAR(*at(-27.0, 43.5), 0.5, 1e-6);  // middle: half way
  EXPECT_FALSE(at(-25.0, 43.5).has_value()); // outside the bounds
  EXPECT_FALSE(w.constraintAt(ConstraintKind::kRiverSlope, {0, 0}).has_value());
}

TEST(WorldSpec, MissingConstraintImage) {
  const auto dir = test_support::tempDir();
  WorldSources sources;
  sources.paramsPath = writeFile(dir / "params.json", R"({"constraints": [
      {"kind": "riverSlope", "image": "gone.png", "bounds": [-28, 43, -26, 44]}]})");
  EXPECT_TRUE(failsWith(loadWorldSpec(sources), ErrorCode::kNotFound,
                        "params: constraints[0]: image '" + (dir / "gone.png").string() + "'"));
}

TEST(WorldSpec, ConstraintAwayFromTheLand) {
  const auto dir = test_support::tempDir();
  writeHalfAndHalf(dir / "m.png");
  WorldSources sources;
  sources.paramsPath = writeFile(dir / "params.json", R"({"constraints": [
      {"kind": "riverSlope", "image": "m.png", "bounds": [43, -28, 44, -26]}]})");
  EXPECT_TRUE(
      failsWith(loadWorldSpec(sources), ErrorCode::kInvalidInput, "do not overlap the coastline"));
}

} // namespace
} // namespace strahler::input
