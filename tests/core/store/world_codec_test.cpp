// Round trips, determinism, the documented layout and the size budget of world files.

#include "world_fixtures.h"
#include "world_proto.h"

#include "strahler/primitives/quantization.h"
#include "strahler/store/world_file.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <iostream>
#include <zlib.h>

namespace strahler::store {
namespace {

using construction::WorldData;
using primitives::quantize;
using primitives::Quantum;
using test_support::makeLargeWorld;
using test_support::makeSmallWorld;
using test_support::worldsEqual;

std::uint64_t littleEndian(const std::string& bytes, std::size_t offset, int count) {
  std::uint64_t v = 0;
  for (int i = count - 1; i >= 0; --i)
    v = (v << 8) | static_cast<unsigned char>(bytes[offset + static_cast<std::size_t>(i)]);
  return v;
}

TEST(WorldCodec, SmallWorldRoundTripsExactly) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const WorldData world = makeSmallWorld(seed);
    STRAHLER_ASSIGN_OR_ASSERT(auto decoded, decodeWorld(encodeWorld(world), "small"));
    EXPECT_TRUE(worldsEqual(decoded, world)) << "seed " << seed;
  }
}

TEST(WorldCodec, LargeWorldRoundTripsExactly) {
  const WorldData world = makeLargeWorld();
  STRAHLER_ASSIGN_OR_ASSERT(auto decoded, decodeWorld(encodeWorld(world), "large"));
  EXPECT_TRUE(worldsEqual(decoded, world));
}

TEST(WorldCodec, ReencodingADecodedWorldGivesTheSameBytes) {
  for (const WorldData& world : {makeSmallWorld(3), makeLargeWorld(200.0)}) {
    const std::string bytes = encodeWorld(world);
    STRAHLER_ASSIGN_OR_ASSERT(auto decoded, decodeWorld(bytes, "w"));
    EXPECT_EQ(encodeWorld(decoded), bytes);
  }
}

TEST(WorldCodec, EncodingIsDeterministic) {
  EXPECT_EQ(encodeWorld(makeSmallWorld(5)), encodeWorld(makeSmallWorld(5)));
  EXPECT_NE(encodeWorld(makeSmallWorld(5)), encodeWorld(makeSmallWorld(6)));
}

TEST(WorldCodec, EmptyWorldRoundTrips) {
  WorldData empty;
  STRAHLER_ASSIGN_OR_ASSERT(auto decoded, decodeWorld(encodeWorld(empty), "empty"));
  EXPECT_TRUE(worldsEqual(decoded, empty));
}

TEST(WorldCodec, ExtremeButValidValuesRoundTrip) {
  WorldData world = makeSmallWorld(2);
  world.name = std::string("not utf-8: \xff\xfe\0 end", 17);
  world.land[0].outer[0] = {-4'000'000.125, 3'999'999.875};
  world.network.nodes[4].elevation = quantize(8848.86, Quantum::kElevation);
  world.network.nodes[4].priority = -7;
  world.flow[0] = quantize(123456.789, Quantum::kFlow);
  world.terrain[0].elevation = quantize(-10994.0, Quantum::kElevation);
  world.terrain[0].roughness = Quantum::kRoughness;
  world.rivers[0].curve[0].elevation = quantize(-0.01, Quantum::kElevation);
  world.network.mouths[0].inward = {0.1234567890123456789, -0.9876543210987654321};
  world.projectionCenter = {-180.0, 90.0};
  world.stageSeconds.push_back({"", 0.0});
  STRAHLER_ASSIGN_OR_ASSERT(auto decoded, decodeWorld(encodeWorld(world), "extreme"));
  EXPECT_TRUE(worldsEqual(decoded, world));
}

TEST(WorldCodec, HeaderFollowsTheDocumentedLayout) {
  const std::string bytes = encodeWorld(makeSmallWorld());
  ASSERT_GE(bytes.size(), kWorldHeaderBytes + kWorldTrailerBytes);
  EXPECT_EQ(bytes.substr(0, 14), std::string("STRAHLERWORLD\0", 14));
  EXPECT_EQ(littleEndian(bytes, 14, 4), kWorldFormatVersionWithoutRelief); // no residual
  EXPECT_EQ(littleEndian(bytes, 18, 8), bytes.size() - 30);
  const std::size_t body = bytes.size() - 4;
  const auto crc = crc32_z(0, reinterpret_cast<const Bytef*>(bytes.data()), body);
  EXPECT_EQ(littleEndian(bytes, body, 4), crc);
}

TEST(WorldCodec, RealisticWorldFitsTheSizeBudget) {
  const WorldData world = makeLargeWorld(1000.0);
  ASSERT_NEAR(world.areaKm2(), 1000.0, 25.0);
  ASSERT_GE(world.terrain.size(), 10'000u);
  ASSERT_GE(world.rivers.size(), 1'000u);
  const std::string bytes = encodeWorld(world);
  const double perKm2 = static_cast<double>(bytes.size()) / world.areaKm2();
  std::cout << "[ budget   ] " << bytes.size() << " bytes for " << world.areaKm2() << " km², "
            << world.terrain.size() << " terrain and " << world.rivers.size()
            << " river primitives: " << perKm2 << " bytes/km²\n";
  const v1::World message = detail::toProto(world);
  const auto perArea = [&](std::size_t n) { return static_cast<double>(n) / world.areaKm2(); };
  std::cout << "[ budget   ] per km²: land " << perArea(message.land().ByteSizeLong())
            << ", network " << perArea(message.network().ByteSizeLong()) << ", blocks "
            << perArea(message.blocks().ByteSizeLong()) << ", terrain "
            << perArea(message.terrain().ByteSizeLong()) << ", rivers "
            << perArea(message.rivers().ByteSizeLong()) << "; params JSON "
            << message.params_json().size() << " bytes\n";
  RecordProperty("bytes_per_km2", std::to_string(perKm2));
  EXPECT_LE(perKm2, 500.0);
}

TEST(WorldCodecDeathTest, EncodingAnUnquantisedValueIsAProgrammerError) {
  WorldData world = makeSmallWorld();
  world.terrain[0].elevation += 0.001;
  EXPECT_DEATH((void)encodeWorld(world), "quantum");
}

TEST(WorldCodecDeathTest, EncodingNonContiguousBlocksIsAProgrammerError) {
  WorldData world = makeSmallWorld();
  world.blocks[0].terrainEnd += 1;
  EXPECT_DEATH((void)encodeWorld(world), "contiguous");
}

} // namespace
} // namespace strahler::store
