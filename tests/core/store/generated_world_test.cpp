#include "result_matchers.h"
#include "test_worlds.h"

#include "strahler/construction/world.h"
#include "strahler/construction/world_builder.h"
#include "strahler/store/cache_key.h"
#include "strahler/store/world_file.h"

#include <gtest/gtest.h>

namespace strahler::store {
namespace {

const construction::WorldData& generatedIsland() {
  static const construction::WorldData world = [] {
    const input::WorldSpec spec = test_support::defaultIslandSpec();
    return test_support::valueOf(
        construction::generateWorldData(spec, cacheKey(spec, construction::kGeneratorVersion)));
  }();
  return world;
}

TEST(GeneratedWorld, FitsTheSizeBudget) {
  const construction::WorldData& world = generatedIsland();
  const double bytesPerKm2 = double(encodeWorld(world).size()) / world.areaKm2();
  EXPECT_LE(bytesPerKm2, 500.0);
  // The paper's density: about 10 terrain primitives per km².
  EXPECT_GT(double(world.terrain.size()) / world.areaKm2(), 7.0);
}

TEST(GeneratedWorld, AnErodedWorldFitsThePapersBudgetAndRoundTrips) {
  input::WorldSpec spec = test_support::defaultIslandSpec();
  spec.params.erosionSteps = 20;
  const construction::WorldData world = test_support::valueOf(
      construction::generateWorldData(spec, cacheKey(spec, construction::kGeneratorVersion)));
  ASSERT_FALSE(world.relief.empty());
  const std::string bytes = encodeWorld(world);
  EXPECT_LE(double(bytes.size()) / world.areaKm2(), 1500.0); // the paper's 1.5 KB per km²
  STRAHLER_ASSIGN_OR_ASSERT(auto decoded, decodeWorld(bytes, "eroded"));
  const construction::WorldData& back = decoded;
  EXPECT_EQ(back.relief, world.relief);
  const construction::World a(world), b(back);
  for (int i = 0; i < 200; ++i) {
    const geometry::Vec2 p{-20000.0 + 211.0 * i, -8000.0 + 77.0 * i};
    ASSERT_EQ(a.height(p, 30.0), b.height(p, 30.0));
  }
}

TEST(GeneratedWorld, RoundTripsExactly) {
  const construction::WorldData& world = generatedIsland();
  const std::string bytes = encodeWorld(world);
  STRAHLER_ASSIGN_OR_ASSERT(auto decoded, decodeWorld(bytes, "island"));
  const construction::WorldData& back = decoded;
  EXPECT_EQ(back.terrain, world.terrain);
  EXPECT_EQ(back.rivers, world.rivers);
  EXPECT_EQ(back.blocks, world.blocks);
  EXPECT_EQ(back.flow, world.flow);
  EXPECT_EQ(back.riverTypes, world.riverTypes);
  ASSERT_EQ(back.network.nodes.size(), world.network.nodes.size());
  for (std::size_t i = 0; i < world.network.nodes.size(); ++i) {
    EXPECT_EQ(back.network.nodes[i].position, world.network.nodes[i].position);
    EXPECT_EQ(back.network.nodes[i].elevation, world.network.nodes[i].elevation);
    EXPECT_EQ(back.network.nodes[i].parent, world.network.nodes[i].parent);
    EXPECT_EQ(back.network.nodes[i].strahler, world.network.nodes[i].strahler);
  }
  EXPECT_EQ(encodeWorld(back), bytes);
  // The loaded world evaluates to the same heights, bit for bit.
  const construction::World a(world), b(back);
  for (int i = 0; i < 200; ++i) {
    const geometry::Vec2 p{-20000.0 + 211.0 * i, -8000.0 + 77.0 * i};
    ASSERT_EQ(a.height(p, 3.0), b.height(p, 3.0));
  }
}

TEST(GeneratedWorld, SameSpecGivesSameBytes) {
  const input::WorldSpec spec = test_support::defaultIslandSpec();
  const auto again =
      construction::generateWorldData(spec, cacheKey(spec, construction::kGeneratorVersion));
  STRAHLER_ASSERT_OK(again);
  EXPECT_EQ(encodeWorld(again.value()), encodeWorld(generatedIsland()));
}

TEST(GeneratedWorld, DamagedFilesAreRejected) {
  const std::string bytes = encodeWorld(generatedIsland());
  for (std::size_t offset = 0; offset < bytes.size(); offset += bytes.size() / 97 + 1) {
    std::string flipped = bytes;
    flipped[offset] = static_cast<char>(flipped[offset] ^ 0x10);
    const auto decoded = decodeWorld(flipped, "flipped");
    ASSERT_FALSE(decoded.ok()) << "bit flip at " << offset;
    EXPECT_EQ(decoded.error().code, base::ErrorCode::kCorrupt);
    const auto truncated = decodeWorld(std::string_view(bytes).substr(0, offset), "truncated");
    ASSERT_FALSE(truncated.ok()) << "truncated at " << offset;
  }
}

} // namespace
} // namespace strahler::store
