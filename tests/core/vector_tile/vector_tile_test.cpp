// The MVT 2.1 encoder: the specification's own geometry examples (4.3.5), read back with the
// generated protobuf types, and round trips through decodeTile.
#include "mvt/vector_tile.pb.h"
#include "result_matchers.h"

#include "strahler/vector_tile/vector_tile.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace strahler::vector_tile {
namespace {

Tile oneFeature(Feature feature) {
  return Tile{{Layer{"layer", kDefaultExtent, {std::move(feature)}}}};
}

/// The geometry stream of the one feature of the one layer of `bytes`, by the generated types.
std::vector<std::uint32_t> geometryOf(const std::string& bytes) {
  strahler::mvt::Tile tile;
  EXPECT_TRUE(tile.ParseFromString(bytes));
  EXPECT_EQ(tile.layers_size(), 1);
  EXPECT_EQ(tile.layers(0).version(), 2u);
  EXPECT_EQ(tile.layers(0).features_size(), 1);
  const auto& g = tile.layers(0).features(0).geometry();
  return {g.begin(), g.end()};
}

TEST(VectorTileEncoder, APointIsTheSpecsExample) {
  // 4.3.5.1: MoveTo(25, 17) is [9, 50, 34].
  const std::string bytes = encodeTile(oneFeature({GeometryType::kPoint, {{{25, 17}}}, {}, 0}));
  EXPECT_EQ(geometryOf(bytes), (std::vector<std::uint32_t>{9, 50, 34}));
}

TEST(VectorTileEncoder, ALineIsTheSpecsExample) {
  // 4.3.5.3: (2,2) (2,10) (10,10) is [9, 4, 4, 18, 0, 16, 16, 0].
  const std::string bytes =
      encodeTile(oneFeature({GeometryType::kLineString, {{{2, 2}, {2, 10}, {10, 10}}}, {}, 0}));
  EXPECT_EQ(geometryOf(bytes), (std::vector<std::uint32_t>{9, 4, 4, 18, 0, 16, 16, 0}));
}

TEST(VectorTileEncoder, APolygonIsTheSpecsExample) {
  // 4.3.5.6: (3,6) (8,12) (20,34) closed is [9, 6, 12, 18, 10, 12, 24, 44, 15].
  const std::vector<Point> ring = {{3, 6}, {8, 12}, {20, 34}};
  EXPECT_GT(ringArea2(ring), 0); // an exterior ring by the spec's formula
  const std::string bytes = encodeTile(oneFeature({GeometryType::kPolygon, {ring}, {}, 0}));
  EXPECT_EQ(geometryOf(bytes), (std::vector<std::uint32_t>{9, 6, 12, 18, 10, 12, 24, 44, 15}));
}

TEST(VectorTileEncoder, KeysAndValuesAreStoredOncePerLayer) {
  Layer layer{"rivers", kDefaultExtent, {}};
  for (int i = 0; i < 3; ++i)
    layer.features.push_back({GeometryType::kLineString,
                              {{{0, i}, {10, i}}},
                              {{"order", std::int64_t{2}}, {"rosgen", std::string("E")}},
                              0});
  const std::string bytes = encodeTile(Tile{{layer}});
  strahler::mvt::Tile tile;
  ASSERT_TRUE(tile.ParseFromString(bytes));
  EXPECT_EQ(tile.layers(0).keys_size(), 2);
  EXPECT_EQ(tile.layers(0).values_size(), 2);
  EXPECT_EQ(tile.layers(0).values(0).sint_value(), 2);
  EXPECT_EQ(tile.layers(0).features(2).tags_size(), 4);
}

TEST(VectorTileEncoder, ATileRoundTripsThroughTheDecoder) {
  Tile tile;
  tile.layers.push_back(
      {"water",
       kDefaultExtent,
       {{GeometryType::kPolygon,
         {{{-64, -64}, {4160, -64}, {4160, 4160}, {-64, 4160}}, {{10, 10}, {10, 90}, {90, 90}}},
         {{"kind", std::string("sea")}},
         0}}});
  tile.layers.push_back({"contours",
                         kDefaultExtent,
                         {{GeometryType::kLineString,
                           {{{0, 0}, {100, -20}, {4000, 4096}}, {{5, 5}, {6, 6}}},
                           {{"elevation", std::int64_t{-250}}, {"index", true}},
                           0}}});
  tile.layers.push_back({"features",
                         kDefaultExtent,
                         {{GeometryType::kPoint,
                           {{{1, 2}}, {{3, 4}}},
                           {{"elevation", 1234.5}, {"name", std::string("Río")}},
                           7}}});
  STRAHLER_ASSIGN_OR_ASSERT(const Tile back, decodeTile(encodeTile(tile)));
  EXPECT_EQ(back, tile);
}

TEST(VectorTileEncoder, RepeatsAndDegeneratePartsAreDropped) {
  Tile tile{{{"l",
              kDefaultExtent,
              {{GeometryType::kLineString, {{{1, 1}, {1, 1}, {2, 2}}, {{5, 5}, {5, 5}}}, {}, 0},
               {GeometryType::kPolygon, {{{0, 0}, {4, 0}, {0, 0}}}, {}, 0}}},
             {"empty", kDefaultExtent, {}}}};
  STRAHLER_ASSIGN_OR_ASSERT(const Tile back, decodeTile(encodeTile(tile)));
  ASSERT_EQ(back.layers.size(), 1u);
  ASSERT_EQ(back.layers[0].features.size(), 1u);
  EXPECT_EQ(back.layers[0].features[0].parts, (std::vector<std::vector<Point>>{{{1, 1}, {2, 2}}}));
}

TEST(VectorTileDecoder, RefusesBytesThatAreNotATile) {
  EXPECT_FALSE(decodeTile("\xff\xff\xff").ok());
  strahler::mvt::Tile tile;
  auto* layer = tile.add_layers();
  layer->set_version(2);
  layer->set_name("l");
  auto* feature = layer->add_features();
  feature->set_type(strahler::mvt::Tile::LINESTRING);
  for (std::uint32_t v : {18u, 2u, 2u}) // a LineTo before any MoveTo
    feature->add_geometry(v);
  EXPECT_FALSE(decodeTile(tile.SerializeAsString()).ok());
  feature->clear_geometry();
  feature->add_tags(0); // a tag without a key
  feature->add_tags(0);
  EXPECT_FALSE(decodeTile(tile.SerializeAsString()).ok());
}

} // namespace
} // namespace strahler::vector_tile
