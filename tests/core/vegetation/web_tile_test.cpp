#include "strahler/vegetation/web_tile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace strahler::vegetation {
namespace {

using geometry::Vec2;

/// A world centred in the Alps; tiles near its centre.
const geometry::LocalProjection kProjection(7.5, 46.5);

geometry::TileId tileAt(Vec2 lonLat, int z) {
  const Vec2 c = tileCoordinates(geometry::TileId{z, 0, 0}, lonLat);
  return {z, static_cast<std::int64_t>(std::floor(c.x)),
          static_cast<std::int64_t>(std::floor(c.y))};
}

TEST(VegetationWebTile, FootprintHoldsItsTileAndOwnsOnlyIt) {
  const geometry::TileId t = tileAt({7.51, 46.49}, 17);
  const Footprint f = webTileFootprint(kProjection, t);
  const double n = std::ldexp(1.0, t.z);
  for (double a : {0.001, 0.5, 0.999})
    for (double b : {0.001, 0.5, 0.999}) {
      const double u = (static_cast<double>(t.x) + a) / n;
      const double v = (static_cast<double>(t.y) + b) / n;
      const Vec2 lonLat{u * 360.0 - 180.0,
                        std::atan(std::sinh(3.141592653589793 * (1.0 - 2.0 * v))) *
                            57.29577951308232};
      const Vec2 p = kProjection.forward(lonLat);
      EXPECT_TRUE(f.bounds.contains(p));
      EXPECT_TRUE(f.contains(p));
      const Vec2 c = tileCoordinates(t, lonLat);
      EXPECT_NEAR(c.x, a, 1e-6);
      EXPECT_NEAR(c.y, b, 1e-6);
    }
  const Footprint east = webTileFootprint(kProjection, geometry::TileId{t.z, t.x + 1, t.y});
  EXPECT_FALSE(east.contains(kProjection.forward(kProjection.inverse(f.bounds.center()))));
}

TEST(VegetationWebTile, FourChildrenUnionEqualsTheirParent) {
  const FunctionDensity d([](std::size_t, Vec2 p) {
    return static_cast<float>(0.6 + 0.4 * std::sin(p.x / 29.0 + p.y / 41.0));
  });
  const geometry::TileId parent = tileAt({7.52, 46.51}, 16);
  const auto whole = placeInstances(7, webTileFootprint(kProjection, parent), d, kAllSpecies);
  std::vector<Instance> children;
  for (std::int64_t j = 0; j < 2; ++j)
    for (std::int64_t i = 0; i < 2; ++i) {
      const geometry::TileId c{17, parent.x * 2 + i, parent.y * 2 + j};
      const auto part = placeInstances(7, webTileFootprint(kProjection, c), d, kAllSpecies);
      EXPECT_FALSE(part.empty());
      children.insert(children.end(), part.begin(), part.end());
    }
  std::sort(children.begin(), children.end(), instanceLess);
  ASSERT_GT(whole.size(), 2000u);
  EXPECT_TRUE(children == whole);
  EXPECT_LE(whole.size(), maxInstancesPerWebTile(16, kAllSpecies));
}

TEST(VegetationWebTile, PlaceWebTileServesOnlyVisibleZooms) {
  const UniformDensity d({0.5f, 0.5f});
  const geometry::TileId t17 = tileAt({7.5, 46.5}, 17);
  const auto result = placeWebTile(3, kProjection, t17, d);
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(result.value() ==
              placeInstances(3, webTileFootprint(kProjection, t17), d, visibleSpecies(17)));
  // Zoom 16 serves trees only.
  const auto trees = placeWebTile(3, kProjection, tileAt({7.5, 46.5}, 16), d);
  ASSERT_TRUE(trees.ok());
  ASSERT_FALSE(trees.value().empty());
  for (const Instance& i : trees.value())
    EXPECT_EQ(i.species, 0);
  for (const geometry::TileId bad :
       {tileAt({7.5, 46.5}, 15), tileAt({7.5, 46.5}, kMaxVegetationZoom + 1),
        geometry::TileId{17, -1, 0}, geometry::TileId{17, 0, std::int64_t{1} << 17}}) {
    const auto r = placeWebTile(3, kProjection, bad, d);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, base::ErrorCode::kOutOfRange);
  }
}

} // namespace
} // namespace strahler::vegetation
