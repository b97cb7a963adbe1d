#include "strahler/vegetation/vegetation_json.h"

#include <gtest/gtest.h>

namespace strahler::vegetation {
namespace {

TEST(VegetationJson, WritesTheDocumentedFormat) {
  const geometry::LocalProjection projection(0.0, 0.0);
  // The tile z18 (131072, 131071) has its south-west corner at (0°, 0°), the local origin.
  const WebTile tile{18, 131072, 131071};
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
      writeVegetationJson(WebTile{17, 5, 6}, geometry::LocalProjection(10.0, 50.0), {});
  EXPECT_NE(json.find("\"tile\":[17,5,6]"), std::string::npos);
  EXPECT_NE(json.find("\"instances\":[]}"), std::string::npos);
}

} // namespace
} // namespace strahler::vegetation
