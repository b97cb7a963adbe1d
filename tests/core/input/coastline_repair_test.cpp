// The coastline reader with and without --repair, on made-up defects and on Natural Earth's
// Iceland (tests/data/iceland.geojson), whose main ring crosses itself once.
#include "input_test_util.h"

#include "strahler/input/canonical_coastline.h"
#include "strahler/input/coastline.h"
#include "strahler/input/world_spec.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace strahler::input {
namespace {

using base::ErrorCode;
using test_support::failsWith;
using test_support::polygonJson;
using test_support::square;

std::string report(const repair::RepairedCoast& coast) {
  std::string text;
  for (const repair::Change& change : coast.changes)
    text += repair::describe(change) + "\n";
  return text;
}

TEST(CoastlineRepair, DefectsTheRepairMendsSayThatItExists) {
  const std::string bowtie = polygonJson({{{0, 0}, {1, 1}, {1, 0}, {0, 1}, {0, 0}}});
  EXPECT_TRUE(failsWith(parseCoastline(bowtie), ErrorCode::kInvalidInput,
                        "ring intersects itself: segment 0 (positions 0-1) touches or crosses "
                        "segment 2 (positions 2-3) at (0.50000, 0.50000); run with --repair to "
                        "mend it"));
  const std::string spike = polygonJson({{{0, 0}, {2, 0}, {1, 0}, {1, 1}, {0, 0}}});
  EXPECT_TRUE(failsWith(parseCoastline(spike), ErrorCode::kInvalidInput,
                        "doubles back at position 1 (a zero-width spike); run with --repair"));
  // Faults of the GeoJSON itself are not the repair's business.
  const std::string open = polygonJson({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  const auto unclosed = parseCoastline(open);
  ASSERT_FALSE(unclosed.ok());
  EXPECT_EQ(unclosed.error().message.find("--repair"), std::string::npos);
  EXPECT_TRUE(
      failsWith(parseAndRepairCoastline(open), ErrorCode::kInvalidInput, "ring not closed"));
}

TEST(CoastlineRepair, RepairedBowtieParsesAndIsReported) {
  const auto repaired =
      parseAndRepairCoastline(polygonJson({{{0, 0}, {1, 1}, {1, 0}, {0, 1}, {0, 0}}}));
  ASSERT_TRUE(repaired.ok()) << repaired.error().message;
  const std::string text = report(repaired.value());
  EXPECT_NE(text.find("self-intersection at (0.50000, 0.50000)"), std::string::npos) << text;
  EXPECT_NE(text.find("polygon 0, ring 0: segments at positions 0-1 and positions 2-3 cross"),
            std::string::npos)
      << text;
  ASSERT_EQ(repaired.value().land.size(), 1u);
  EXPECT_NEAR(geometry::area(repaired.value().land), 0.5, 1e-6);
}

TEST(CoastlineRepair, ValidCoastlineIsTheSameWithOrWithoutRepair) {
  const std::string json =
      polygonJson({square(0, 0, 1), {{0.2, 0.2}, {0.2, 0.4}, {0.4, 0.4}, {0.4, 0.2}, {0.2, 0.2}}});
  const auto plain = parseCoastline(json);
  const auto repaired = parseAndRepairCoastline(json);
  STRAHLER_ASSERT_OK(plain);
  STRAHLER_ASSERT_OK(repaired);
  EXPECT_TRUE(repaired.value().changes.empty()) << report(repaired.value());
  ASSERT_EQ(repaired.value().land.size(), 1u);
  EXPECT_EQ(repaired.value().land[0].outer, plain.value()[0].outer);
  EXPECT_EQ(repaired.value().land[0].holes, plain.value()[0].holes);
}

TEST(CoastlineRepair, IcelandIsRefusedNamingTheCrossingAndRepair) {
  const auto land = parseCoastline(test_support::readTestData("iceland.geojson"));
  EXPECT_TRUE(failsWith(land, ErrorCode::kInvalidInput,
                        "feature 0, polygon 0, ring 0: ring intersects itself: segment 511 "
                        "(positions 511-512) touches or crosses segment 513 (positions 513-514) "
                        "at (-16.48276, 63.90223); run with --repair to mend it"));
}

TEST(CoastlineRepair, IcelandIsRepairedWithAReportOfEachChange) {
  STRAHLER_ASSIGN_OR_ASSERT(const auto repaired,
                            parseAndRepairCoastline(test_support::readTestData("iceland.geojson")));
  const repair::RepairedCoast& coast = repaired;
  const std::string text = report(coast);
  // Natural Earth's ring runs clockwise and crosses itself once, on the south-east coast at
  // 16.48 W, 63.90 N, cutting off a loop of about 0.04 km² that touches the rest at the
  // crossing and is joined to it there.
  ASSERT_EQ(coast.changes.size(), 3u) << text;
  EXPECT_EQ(coast.changes[0].kind, repair::ChangeKind::kOrientation);
  const repair::Change& crossing = coast.changes[1];
  EXPECT_EQ(crossing.kind, repair::ChangeKind::kSelfIntersection) << text;
  EXPECT_NEAR(crossing.lonLat.x, -16.48276, 1e-5);
  EXPECT_NEAR(crossing.lonLat.y, 63.90223, 1e-5);
  EXPECT_GT(crossing.areaKm2, 0.01);
  EXPECT_LT(crossing.areaKm2, 0.1);
  EXPECT_NE(crossing.description.find("segments at positions 511-512 and positions 513-514 cross"),
            std::string::npos)
      << text;
  EXPECT_EQ(coast.changes[2].kind, repair::ChangeKind::kPinch) << text;
  EXPECT_EQ(coast.changes[2].lonLat, crossing.lonLat);
  EXPECT_LT(coast.changes[2].areaKm2, 2e-4);
  ASSERT_EQ(coast.land.size(), 1u);
  EXPECT_GT(coast.land[0].outer.size(), 3000u);
  EXPECT_GT(geometry::signedArea(coast.land[0].outer), 0.0); // counter-clockwise now
}

TEST(CoastlineRepair, WorldSpecOfIcelandKeysTheRepairedGeometry) {
  WorldSources sources;
  sources.coastPath = std::string(STRAHLER_TEST_DATA_DIR) + "/iceland.geojson";
  EXPECT_TRUE(failsWith(loadWorldSpec(sources), ErrorCode::kInvalidInput,
                        "iceland.geojson: coastline: feature 0, polygon 0, ring 0: ring "
                        "intersects itself"));
  sources.repair = true;
  STRAHLER_ASSIGN_OR_ASSERT(const auto spec, loadWorldSpec(sources));
  EXPECT_EQ(spec.repairs.size(), 3u);
  // Iceland: 101,689 km² with its islets (Natural Earth); the main island alone is a little
  // less. The land the world is built from, and keyed by, is the repaired one.
  EXPECT_NEAR(spec.areaKm2(), 101'000.0, 1'500.0);
  STRAHLER_ASSIGN_OR_ASSERT(auto direct,
                            parseAndRepairCoastline(test_support::readTestData("iceland.geojson")));
  canonicalizeCoastline(direct.land); // the spec's land starts at its smallest vertex
  ASSERT_EQ(spec.landLonLat.size(), 1u);
  EXPECT_EQ(spec.landLonLat[0].outer, direct.land[0].outer);
}

TEST(CoastlineRepair, RandomSelfCrossingRingsGiveValidLandOrAPreciseError) {
  // Rings of 3 to 14 vertices on a coarse grid: crossings, touches, shared vertices and
  // collinear overlaps everywhere. The repaired land passes every check of the reader (it
  // runs them); the rare failure is an invalid-input error naming the repair, never a crash.
  std::uint64_t state = 12345;
  auto next = [&state](int n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<int>((state >> 33) % static_cast<std::uint64_t>(n));
  };
  int repaired = 0;
  for (int iteration = 0; iteration < 300; ++iteration) {
    std::vector<test_support::RingPositions> rings;
    for (int r = 0; r < 1 + iteration % 2; ++r) {
      test_support::RingPositions ring;
      const int n = 3 + next(12);
      for (int i = 0; i < n; ++i)
        ring.push_back({10.0 + 0.01 * next(7), 40.0 + 0.01 * next(7)});
      ring.push_back(ring.front());
      rings.push_back(ring);
    }
    const std::string json = polygonJson(rings);
    const auto first = parseAndRepairCoastline(json);
    const auto second = parseAndRepairCoastline(json);
    ASSERT_EQ(first.ok(), second.ok());
    if (!first.ok()) {
      EXPECT_EQ(first.error().code, ErrorCode::kInvalidInput) << first.error().message;
      EXPECT_EQ(first.error().message.find("the repair left a defect"), std::string::npos)
          << "the repair's output failed the reader's checks: " << first.error().message;
      EXPECT_EQ(first.error().message, second.error().message);
      continue;
    }
    ++repaired;
    ASSERT_EQ(first.value().land.size(), second.value().land.size());
    for (std::size_t p = 0; p < first.value().land.size(); ++p)
      EXPECT_EQ(first.value().land[p].outer, second.value().land[p].outer);
  }
  EXPECT_GT(repaired, 270);
}

} // namespace
} // namespace strahler::input
