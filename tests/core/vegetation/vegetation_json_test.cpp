#include "strahler/vegetation/vegetation_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <set>

namespace strahler::vegetation {
namespace {

/// The zoom-z tile holding the projection's centre.
geometry::TileId tileNear(const geometry::LocalProjection& projection, int z) {
  const geometry::Vec2 c = tileCoordinates(geometry::TileId{z, 0, 0}, projection.center());
  return {z, static_cast<std::int64_t>(std::floor(c.x)),
          static_cast<std::int64_t>(std::floor(c.y))};
}

TEST(VegetationJson, WritesTheDocumentedFormat) {
  const geometry::LocalProjection projection(0.0, 0.0);
  // The tile z18 (131072, 131071) has its south-west corner at (0°, 0°), the local origin.
  const geometry::TileId tile{18, 131072, 131071};
  Instance inst;
  inst.position = {0.0, 0.0};
  inst.species = 1;
  inst.radius = 1.25f;
  inst.rotation = 0.5f;
  inst.scale = 1.125f;
  inst.id = 0xABCDEF0123456789ull;
  const std::vector<Instance> instances{inst};
  EXPECT_EQ(writeVegetationJson(tile, projection, instances),
            "{\"tile\":[18,131072,131071],\"species\":["
            "{\"name\":\"tree\",\"spacing\":4.00,\"max_radius\":6.00},"
            "{\"name\":\"bush\",\"spacing\":2.00,\"max_radius\":1.80}],\"instances\":["
            "{\"species\":1,\"x\":0.0000000,\"y\":1.0000000,\"lon\":0.0000000,\"lat\":0.0000000,"
            "\"radius\":1.25,\"rotation\":0.500,\"scale\":1.125,\"id\":\"abcdef0123456789\"}]}");
}

TEST(VegetationJson, EmptyTileHasAnEmptyList) {
  const std::string json =
      writeVegetationJson(geometry::TileId{17, 5, 6}, geometry::LocalProjection(10.0, 50.0), {});
  EXPECT_NE(json.find("\"tile\":[17,5,6]"), std::string::npos);
  EXPECT_NE(json.find("\"instances\":[]}"), std::string::npos);
}

TEST(VegetationJson, ATilesJsonParsesAndPointsBackToItsInstances) {
  const geometry::LocalProjection projection(-21.9, 64.1);
  const geometry::TileId t = tileNear(projection, 17);
  const UniformDensity density({0.5f, 0.5f});
  const auto instances = placeWebTile(11, projection, t, density).value();
  ASSERT_GT(instances.size(), 100u);
  const auto json = nlohmann::json::parse(writeVegetationJson(t, projection, instances));
  EXPECT_EQ(json["tile"], nlohmann::json::array({t.z, t.x, t.y}));
  ASSERT_EQ(json["species"].size(), kSpecies.size());
  EXPECT_EQ(json["species"][0]["name"], "tree");
  const auto& list = json["instances"];
  ASSERT_EQ(list.size(), instances.size());
  std::set<std::string> ids;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const auto& o = list[i];
    EXPECT_EQ(o["species"].get<int>(), instances[i].species);
    const double x = o["x"].get<double>(), y = o["y"].get<double>();
    EXPECT_GE(x, 0.0);
    EXPECT_LE(x, 1.0);
    EXPECT_GE(y, 0.0);
    EXPECT_LE(y, 1.0);
    // 7 decimals of a degree: back within 2 cm of the local position.
    const geometry::Vec2 back =
        projection.forward({o["lon"].get<double>(), o["lat"].get<double>()});
    EXPECT_LT(geometry::distance(back, instances[i].position), 0.02);
    EXPECT_NEAR(o["radius"].get<double>(), instances[i].radius, 0.005);
    ids.insert(o["id"].get<std::string>());
  }
  EXPECT_EQ(ids.size(), instances.size());
}

} // namespace
} // namespace strahler::vegetation
