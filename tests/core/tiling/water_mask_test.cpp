#include "result_matchers.h"
#include "test_worlds.h"

#include "strahler/construction/world_builder.h"
#include "strahler/tiling/water_mask.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace strahler::tiling {
namespace {

using geometry::Aabb;
using geometry::Vec2;

const construction::World& island() {
  static const construction::World world(test_support::valueOf(
      construction::generateWorldData(test_support::defaultIslandSpec(), "water")));
  return world;
}

geometry::LocalProjection projectionOf(const construction::World& world) {
  return {world.data().projectionCenter.x, world.data().projectionCenter.y};
}

/// The island's land box in degrees.
Aabb landDegrees(const construction::World& world) {
  const geometry::LocalProjection projection = projectionOf(world);
  Aabb box;
  for (const geometry::Polygon& p : world.data().land)
    for (Vec2 v : p.outer)
      box.add(projection.inverse(v));
  return box;
}

/// The local point of mask cell (i, j) of `lonLat`.
Vec2 cellCentre(const geometry::LocalProjection& projection, const Aabb& lonLat, int i, int j) {
  const Vec2 size = lonLat.size() * (1.0 / WaterMask::kSize);
  return projection.forward({lonLat.min.x + (i + 0.5) * size.x, lonLat.max.y - (j + 0.5) * size.y});
}

TEST(WaterMask, OpenSeaIsOneWaterByte) {
  const WaterMask mask(island(), projectionOf(island()));
  const Aabb land = landDegrees(island());
  const Aabb far{{land.max.x + 1.0, land.min.y}, {land.max.x + 1.5, land.min.y + 0.5}};
  EXPECT_EQ(mask.of(far), std::vector<std::uint8_t>{WaterMask::kWater});
}

TEST(WaterMask, TheWholeIslandIsLandAndSeaCellForCellAsTheCoastlineSays) {
  const construction::World& world = island();
  const geometry::LocalProjection projection = projectionOf(world);
  const WaterMask mask(world, projection);
  const Aabb box = landDegrees(world).expanded(0.01);
  const std::vector<std::uint8_t> cells = mask.of(box);
  ASSERT_EQ(cells.size(), static_cast<std::size_t>(WaterMask::kSize * WaterMask::kSize));
  int land = 0, sea = 0, riverOnLand = 0;
  for (int j = 0; j < WaterMask::kSize; ++j)
    for (int i = 0; i < WaterMask::kSize; ++i) {
      const std::uint8_t v = cells[static_cast<std::size_t>(j * WaterMask::kSize + i)];
      const bool onLand = world.land().contains(cellCentre(projection, box, i, j));
      ASSERT_TRUE(v == 0 || v == WaterMask::kWater);
      if (!onLand) {
        EXPECT_EQ(v, WaterMask::kWater) << i << "," << j; // sea and lakes are always water
        ++sea;
      } else if (v == 0) {
        ++land;
      } else {
        ++riverOnLand;
      }
    }
  EXPECT_GT(land, 10000);
  EXPECT_GT(sea, 10000);
  // Cells here are ~200 m: no river of the island is that wide.
  EXPECT_EQ(riverOnLand, 0);
}

TEST(WaterMask, RiversAtLeastOneCellWideAreWater) {
  const construction::World& world = island();
  const geometry::LocalProjection projection = projectionOf(world);
  const WaterMask mask(world, projection);
  // The widest river section: a box of 64 of its widths around its downstream end.
  const auto& rivers = world.data().rivers;
  const auto widest = std::max_element(rivers.begin(), rivers.end(),
                                       [](auto& a, auto& b) { return a.widthDown < b.widthDown; });
  ASSERT_NE(widest, rivers.end());
  const primitives::CurvePoint& mid = widest->curve[widest->curve.size() / 2];
  const double width = widest->widthDown;
  ASSERT_GT(width, 5.0);
  const Vec2 centre = projection.inverse(mid.position);
  const double degrees = 64.0 * width / 111000.0;
  const Aabb box{{centre.x - degrees, centre.y - 0.5 * degrees},
                 {centre.x + degrees, centre.y + 0.5 * degrees}};
  const std::vector<std::uint8_t> cells = mask.of(box);
  ASSERT_EQ(cells.size(), static_cast<std::size_t>(WaterMask::kSize * WaterMask::kSize));
  // The river segments near the box, with the largest half width of their river.
  struct Segment {
    Vec2 a, b;
    double half = 0.0;
    bool widest = false;
  };
  Aabb local;
  for (int k : {0, WaterMask::kSize - 1})
    for (int l : {0, WaterMask::kSize - 1})
      local.add(cellCentre(projection, box, k, l));
  local = local.expanded(4.0 * width);
  std::vector<Segment> near;
  for (const auto& r : rivers)
    for (std::size_t k = 1; k < r.curve.size(); ++k)
      if (local.contains(r.curve[k - 1].position) || local.contains(r.curve[k].position))
        near.push_back({r.curve[k - 1].position, r.curve[k].position,
                        0.5 * std::max(r.widthUp, r.widthDown), &r == &*widest});
  int onRiverLand = 0, offRiverWater = 0;
  for (int j = 0; j < WaterMask::kSize; ++j)
    for (int i = 0; i < WaterMask::kSize; ++i) {
      const Vec2 p = cellCentre(projection, box, i, j);
      if (!world.land().contains(p))
        continue;
      bool insideWidest = false, insideAny = false;
      for (const Segment& s : near) {
        const Vec2 ab = s.b - s.a;
        const double t = std::clamp(dot(p - s.a, ab) / std::max(dot(ab, ab), 1e-12), 0.0, 1.0);
        const double d = geometry::distance(p, s.a + ab * t);
        insideAny = insideAny || d <= s.half + 1e-6;
        insideWidest =
            insideWidest || (s.widest && d < 0.45 * std::min(widest->widthUp, widest->widthDown));
      }
      const bool water = cells[static_cast<std::size_t>(j * WaterMask::kSize + i)] != 0;
      if (insideWidest && !water)
        ++onRiverLand;
      if (water && !insideAny)
        ++offRiverWater;
    }
  EXPECT_EQ(onRiverLand, 0);   // the channel of the widest river is water
  EXPECT_EQ(offRiverWater, 0); // and nothing beyond any channel's half width is
  EXPECT_GT(std::count(cells.begin(), cells.end(), WaterMask::kWater), 100);
}

} // namespace
} // namespace strahler::tiling
