#include "result_matchers.h"
#include "test_worlds.h"

#include "strahler/geometry/polygon_index.h"
#include "strahler/network/mouth_placement.h"

#include <gtest/gtest.h>

namespace strahler::network {
namespace {

TEST(MouthPlacement, MouthsAreOnTheShoreAndSpreadApart) {
  const input::WorldSpec spec = test_support::defaultIslandSpec();
  const geometry::PolygonIndex land(spec.land);
  STRAHLER_ASSIGN_OR_ASSERT(auto mouths, placeMouths(spec, land));
  ASSERT_GT(mouths.size(), 5u);
  const auto& m = mouths;
  for (std::size_t i = 0; i < m.size(); ++i) {
    EXPECT_LT(land.distanceToBoundary(m[i].position, 1.0), 1e-6);
    EXPECT_NEAR(geometry::length(m[i].inward), 1.0, 1e-9);
    EXPECT_TRUE(land.contains(m[i].position + m[i].inward * spec.params.edgeLength));
    for (std::size_t j = i + 1; j < m.size(); ++j)
      EXPECT_GE(geometry::distance(m[i].position, m[j].position), spec.params.sigma);
  }
}

TEST(MouthPlacement, TheMostConcaveMouthsGetTheHighestPriority) {
  const input::WorldSpec spec = test_support::defaultIslandSpec();
  const geometry::PolygonIndex land(spec.land);
  STRAHLER_ASSIGN_OR_ASSERT(const auto mouths, placeMouths(spec, land));
  const MouthSite* best = nullptr;
  int maxPriority = 0;
  for (const MouthSite& m : mouths) {
    if (m.onLake)
      continue;
    if (!best || m.accessibility > best->accessibility)
      best = &m;
    maxPriority = std::max(maxPriority, m.priority);
  }
  ASSERT_NE(best, nullptr);
  EXPECT_EQ(best->priority, spec.params.maxPriority);
  EXPECT_EQ(maxPriority, spec.params.maxPriority);
  // Priorities fall off like Strahler orders: few high, many low.
  std::size_t top = 0, low = 0;
  for (const MouthSite& m : mouths)
    (m.priority == spec.params.maxPriority ? top : low) += 1;
  EXPECT_EQ(top, 1u);
  EXPECT_GT(low, top);
}

TEST(MouthPlacement, LakeShoresGetLowPriorityMouths) {
  const input::WorldSpec spec = test_support::defaultIslandSpec();
  const geometry::PolygonIndex land(spec.land);
  STRAHLER_ASSIGN_OR_ASSERT(const std::vector<MouthSite> mouths, placeMouths(spec, land));
  std::size_t onLake = 0;
  for (const MouthSite& m : mouths)
    if (m.onLake) {
      ++onLake;
      EXPECT_EQ(m.priority, 1);
    }
  EXPECT_GT(onLake, 0u)
      << "the default island's lake gets no mouth: the check above proves nothing";
}

TEST(MouthPlacement, UserMouthsReplaceAutomaticOnesAndSnapToTheShore) {
  input::WorldSpec spec = test_support::defaultIslandSpec();
  const geometry::PolygonIndex land(spec.land);
  const geometry::Vec2 shore = spec.land[0].outer[100];
  spec.mouths.push_back({{0, 0}, shore + geometry::Vec2{150, 150}, 4});
  STRAHLER_ASSIGN_OR_ASSERT(const auto mouths, placeMouths(spec, land));
  ASSERT_EQ(mouths.size(), 1u);
  EXPECT_EQ(mouths[0].priority, 4);
  EXPECT_LT(land.distanceToBoundary(mouths[0].position, 1.0), 1e-6);
}

TEST(MouthPlacement, UserMouthFarFromTheShoreIsAnError) {
  input::WorldSpec spec = test_support::defaultIslandSpec();
  const geometry::PolygonIndex land(spec.land);
  spec.mouths.push_back({{-27.0, 44.0}, {0.0, 0.0}, 2}); // the island's centre
  const auto mouths = placeMouths(spec, land);
  ASSERT_FALSE(mouths.ok());
  EXPECT_NE(mouths.error().message.find("more than 5 km from any shore"), std::string::npos);
}

} // namespace
} // namespace strahler::network
