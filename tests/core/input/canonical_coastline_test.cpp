#include "coastline_variants.h"
#include "input_test_util.h"

#include "strahler/input/canonical_coastline.h"
#include "strahler/input/coastline.h"
#include "strahler/input/world_spec.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace strahler::input {
namespace {

using base::ErrorCode;
using geometry::Ring;
using geometry::Vec2;
using strahler::test_support::CoastlineRewrite;
using strahler::test_support::rewriteCoastline;
using test_support::failsWith;
using test_support::readTestData;

/// The spec of a coastline given as text (with --repair when it needs it).
WorldSpec specOf(const std::string& geojson, bool repair) {
  auto spec = makeWorldSpec("coast", geojson, Params{}, InputLimits{}, repair);
  EXPECT_TRUE(spec.ok()) << (spec.ok() ? "" : spec.error().message);
  return spec.ok() ? std::move(spec).value() : WorldSpec{};
}

/// Every coastline of tests/data and the embedded island; Iceland crosses itself (--repair).
struct Coast {
  std::string name;
  std::string geojson;
  bool repair = false;
};

std::vector<Coast> everyCoastline() {
  return {{"default island", std::string(defaultCoastlineGeoJson()), false},
          {"mallorca", readTestData("mallorca.geojson"), false},
          {"corsica", readTestData("corsica.geojson"), false},
          {"iceland", readTestData("iceland.geojson"), true}};
}

/// What the world and its cache key are made from: the canonical land in degrees, the land in
/// the local frame, and the frame's centre.
void expectSameLand(const WorldSpec& a, const WorldSpec& b, const std::string& what) {
  EXPECT_EQ(a.landLonLat.size(), b.landLonLat.size()) << what;
  for (std::size_t p = 0; p < std::min(a.landLonLat.size(), b.landLonLat.size()); ++p) {
    EXPECT_TRUE(a.landLonLat[p].outer == b.landLonLat[p].outer) << what << ", polygon " << p;
    EXPECT_TRUE(a.landLonLat[p].holes == b.landLonLat[p].holes) << what << ", polygon " << p;
    EXPECT_TRUE(a.land[p].outer == b.land[p].outer) << what << ", local polygon " << p;
    EXPECT_TRUE(a.land[p].holes == b.land[p].holes) << what << ", local polygon " << p;
  }
  EXPECT_EQ(a.projection.center(), b.projection.center()) << what;
}

TEST(CanonicalCoastline, EveryCoastlineGivesTheSameLandWhicheverWayItsRingsRunAndStart) {
  int compared = 0;
  for (const Coast& coast : everyCoastline()) {
    const WorldSpec original = specOf(coast.geojson, coast.repair);
    ASSERT_FALSE(original.landLonLat.empty()) << coast.name;
    for (const CoastlineRewrite how :
         {CoastlineRewrite{true, 0, false}, CoastlineRewrite{false, 7, false},
          CoastlineRewrite{true, 101, false}, CoastlineRewrite{false, 1, true}}) {
      const std::string what = coast.name + (how.reverseRings ? ", reversed" : "") + ", started " +
                               std::to_string(how.rotateStart) + " later";
      const std::string rewritten = rewriteCoastline(coast.geojson, how);
      ASSERT_NE(rewritten, rewriteCoastline(coast.geojson, {})) << what; // the text did change
      expectSameLand(specOf(rewritten, coast.repair), original, what);
      ++compared;
    }
  }
  EXPECT_EQ(compared, 16);
}

TEST(CanonicalCoastline, OuterRingsRunCounterClockwiseFromTheirSmallestVertex) {
  for (const Coast& coast : everyCoastline()) {
    const WorldSpec spec = specOf(coast.geojson, coast.repair);
    for (const geometry::Polygon& polygon : spec.landLonLat) {
      EXPECT_GT(geometry::signedArea(polygon.outer), 0.0) << coast.name;
      for (const Vec2 v : polygon.outer)
        EXPECT_TRUE(polygon.outer.front().x < v.x ||
                    (polygon.outer.front().x == v.x && polygon.outer.front().y <= v.y))
            << coast.name;
      for (const Ring& hole : polygon.holes)
        EXPECT_LT(geometry::signedArea(hole), 0.0) << coast.name;
    }
  }
}

TEST(CanonicalCoastline, HolesAndPolygonsAreOrderedByTheirFirstVertex) {
  // Two islands, the first with two lakes, written east to west and every ring clockwise.
  const Ring westIsland = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  const Ring eastIsland = {{3, 0}, {3, 1}, {4, 1}, {4, 0}};
  const Ring southLake = {{0.6, 0.2}, {0.8, 0.2}, {0.8, 0.4}, {0.6, 0.4}};
  const Ring northLake = {{0.2, 0.6}, {0.4, 0.6}, {0.4, 0.8}, {0.2, 0.8}};
  geometry::MultiPolygon land = {{eastIsland, {}}, {westIsland, {southLake, northLake}}};
  canonicalizeCoastline(land);
  ASSERT_EQ(land.size(), 2u);
  EXPECT_EQ(land[0].outer, (Ring{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
  EXPECT_EQ(land[1].outer, (Ring{{3, 0}, {4, 0}, {4, 1}, {3, 1}}));
  ASSERT_EQ(land[0].holes.size(), 2u);
  // Holes run clockwise from their smallest vertex; (0.2, 0.6) comes before (0.6, 0.2).
  EXPECT_EQ(land[0].holes[0], (Ring{{0.2, 0.6}, {0.2, 0.8}, {0.4, 0.8}, {0.4, 0.6}}));
  EXPECT_EQ(land[0].holes[1], (Ring{{0.6, 0.2}, {0.6, 0.4}, {0.8, 0.4}, {0.8, 0.2}}));
  // Canonical input stays as it is.
  const geometry::MultiPolygon again = land;
  canonicalizeCoastline(land);
  for (std::size_t p = 0; p < land.size(); ++p) {
    EXPECT_EQ(land[p].outer, again[p].outer);
    EXPECT_EQ(land[p].holes, again[p].holes);
  }
}

TEST(CanonicalCoastline, LandOnTheEquatorNearThePrimeMeridianLooksSwapped) {
  // Mallorca is not doubted; a place at 0.5 E, 45 N written [lat, lon] is.
  EXPECT_TRUE(specOf(readTestData("mallorca.geojson"), false).warnings.empty());
  const std::string swapped = R"({"type":"Polygon","coordinates":)"
                              R"([[[45,0.4],[45.2,0.4],[45.2,0.6],[45,0.6],[45,0.4]]]})";
  const WorldSpec spec = specOf(swapped, false);
  ASSERT_EQ(spec.warnings.size(), 1u);
  EXPECT_NE(spec.warnings[0].find("[latitude, longitude]"), std::string::npos) << spec.warnings[0];
  EXPECT_NE(spec.warnings[0].find("GeoJSON positions are [longitude, latitude]"),
            std::string::npos);
  // Land on the equator far from the prime meridian (Borneo's longitudes) is not doubted.
  const std::string borneo = R"({"type":"Polygon","coordinates":)"
                             R"([[[110,0.4],[110.2,0.4],[110.2,0.6],[110,0.6],[110,0.4]]]})";
  EXPECT_TRUE(specOf(borneo, false).warnings.empty());
}

TEST(CanonicalCoastline, ALatitudeBeyondThePoleNamesTheLikelySwap) {
  // Tokyo Bay (139.7 E, 35.6 N) written [lat, lon]: latitude 139.6, and a longitude that could
  // be a latitude.
  const std::string swapped = R"({"type":"Polygon","coordinates":)"
                              R"([[[35.5,139.6],[35.5,139.8],[35.7,139.8],[35.7,139.6],)"
                              R"([35.5,139.6]]]})";
  EXPECT_TRUE(failsWith(parseCoastline(swapped), ErrorCode::kOutOfRange,
                        "latitude 139.6 is outside [-90, 90]; are the coordinates swapped? "
                        "GeoJSON positions are [longitude, latitude]"));
  // A longitude that cannot be a latitude either: no guess.
  const std::string wild = R"({"type":"Polygon","coordinates":)"
                           R"([[[139.6,92.9],[139.7,92.9],[139.7,93],[139.6,93],[139.6,92.9]]]})";
  auto refused = parseCoastline(wild);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().message.find("swapped"), std::string::npos);
}

} // namespace
} // namespace strahler::input
