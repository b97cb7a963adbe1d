// The artist's vector map in the world file and the cache key: kept bit for bit, absent
// (same bytes, same key) when nothing was drawn, and damaged feature data refused.

#include "world_fixtures.h"
#include "world_proto.h"

#include "strahler/store/cache_key.h"
#include "strahler/store/world_file.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace strahler::store {
namespace {

using base::ErrorCode;
using test_support::failsWith;
using test_support::makeSmallWorld;
using test_support::worldsEqual;

input::Features someFeatures() {
  input::Features f;
  f.mountains.push_back({{8.9456, 42.3797}, {-0.0, 1234.5678901234567}, 2706.0, std::nullopt});
  f.mountains.push_back({{9.0567, 42.2178}, {0.1, -0.2}, std::nullopt, 4500.25});
  f.ridges.push_back({{{8.83, 42.44}, {8.95, 42.38}}, {{-1.5, 2.5}, {3.0e-300, 4.0}}, 1800.0});
  f.ridges.push_back({{{9.06, 42.22}, {9.13, 42.07}}, {{1.0, 2.0}, {3.0, 4.0}}, std::nullopt});
  f.rivers.push_back({{{9.04, 42.28}, {9.08, 42.4}, {9.531, 42.547}},
                      {{1.0, 1.0}, {2.0, 2.0}, {3.0, 3.0}},
                      std::string("Golo\0\xff", 6)});
  f.rivers.push_back({{{9.12, 42.27}, {9.5451, 42.1032}}, {{5.0, 5.0}, {6.0, 6.0}}, ""});
  return f;
}

bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

TEST(WorldFeatures, RoundTripBitForBit) {
  construction::WorldData world = makeSmallWorld(3);
  world.features = someFeatures();
  STRAHLER_ASSIGN_OR_ASSERT(auto read, decodeWorld(encodeWorld(world), "w"));
  EXPECT_TRUE(worldsEqual(read, world));
  ASSERT_EQ(read.features.mountains.size(), 2u);
  EXPECT_TRUE(sameBits(read.features.mountains[0].position.x, -0.0));
  EXPECT_FALSE(read.features.mountains[0].radius.has_value());
  EXPECT_FALSE(read.features.mountains[1].elevation.has_value());
  EXPECT_TRUE(sameBits(read.features.ridges[0].line[1].x, 3.0e-300));
  EXPECT_EQ(read.features.rivers[0].name, std::string("Golo\0\xff", 6));
  // And the bytes are stable: encoding what was read gives the same file.
  EXPECT_EQ(encodeWorld(read), encodeWorld(world));
}

TEST(WorldFeatures, AWorldWithoutFeaturesWritesNoFeatureField) {
  const construction::WorldData world = makeSmallWorld(3);
  EXPECT_FALSE(detail::toProto(world).has_features());
  construction::WorldData drawn = world;
  drawn.features = someFeatures();
  EXPECT_TRUE(detail::toProto(drawn).has_features());
  EXPECT_GT(encodeWorld(drawn).size(), encodeWorld(world).size());
}

void expectRefused(const std::function<void(v1::Features&)>& damage, const std::string& part) {
  construction::WorldData world = makeSmallWorld(3);
  world.features = someFeatures();
  v1::World message = detail::toProto(world);
  damage(*message.mutable_features());
  EXPECT_TRUE(
      failsWith(detail::fromProto(message, "w"), ErrorCode::kCorrupt, "world file 'w': " + part));
}

TEST(WorldFeatures, DamagedFeatureDataIsCorrupt) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectRefused([](v1::Features& f) { f.mutable_mountains(0)->clear_lat(); },
                "feature mountain 0 lacks its position");
  expectRefused([](v1::Features& f) { f.mutable_mountains(1)->set_lon(200.0); },
                "feature mountain 1 has a (lon, lat) that is not in degrees");
  expectRefused([&](v1::Features& f) { f.mutable_mountains(0)->set_y(nan); },
                "feature mountain 0 has a non-finite local position");
  expectRefused([](v1::Features& f) { f.mutable_mountains(0)->set_elevation(-3.0); },
                "feature mountain 0 elevation is not a finite number > 0");
  expectRefused([&](v1::Features& f) { f.mutable_mountains(1)->set_radius(nan); },
                "feature mountain 1 radius is not a finite number > 0");
  expectRefused(
      [](v1::Features& f) { f.mutable_ridges(1)->mutable_line()->mutable_x()->RemoveLast(); },
      "feature ridge 1 has columns of 2, 2, 1 and 2 values");
  expectRefused([](v1::Features& f) { f.mutable_rivers(1)->clear_line(); },
                "feature river 1 has columns of 0, 0, 0 and 0 values");
  expectRefused([&](v1::Features& f) { f.mutable_rivers(0)->mutable_line()->set_lat(2, nan); },
                "feature river 0 point 2 has a (lon, lat) that is not in degrees");
  expectRefused([](v1::Features& f) { f.mutable_ridges(0)->set_elevation(0.0); },
                "feature ridge 0 elevation is not a finite number > 0");
}

TEST(WorldFeatures, EveryBitFlipInTheFeaturesIsRefused) {
  construction::WorldData world = makeSmallWorld(3);
  const std::size_t plain = encodeWorld(world).size();
  world.features = someFeatures();
  const std::string bytes = encodeWorld(world);
  // The feature field is written last, before the checksum.
  for (std::size_t at = plain - 4; at + 4 < bytes.size(); ++at) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
    auto decoded = decodeWorld(damaged, "flip");
    ASSERT_FALSE(decoded.ok()) << "flip at " << at;
    ASSERT_EQ(decoded.error().code, ErrorCode::kCorrupt);
  }
}

input::WorldSpec islandSpec() {
  auto spec = input::makeWorldSpec(
      "island",
      R"({"type":"Polygon","coordinates":[[[8.5,42.0],[8.62,42.0],[8.62,42.1],[8.5,42.1],[8.5,42.0]]]})",
      input::Params{});
  return strahler::test_support::valueOf(std::move(spec));
}

TEST(CacheKeyFeatures, NoFeaturesLeaveTheCanonicalTextAsBefore) {
  const input::WorldSpec spec = islandSpec();
  EXPECT_EQ(canonicalSpecText(spec, "0.1.0").find("features"), std::string::npos);
  input::WorldSpec drawn = spec;
  drawn.features = someFeatures();
  const std::string text = canonicalSpecText(drawn, "0.1.0");
  EXPECT_EQ(text.substr(0, canonicalSpecText(spec, "0.1.0").size()),
            canonicalSpecText(spec, "0.1.0"));
  EXPECT_NE(text.find("features 2 2 2\nmountain 1 8.9456 42.3797 2706 -\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("name 6:Golo"), std::string::npos) << text;
}

TEST(CacheKeyFeatures, SameFeaturesSameKeyAnyChangeAnotherKey) {
  input::WorldSpec spec = islandSpec();
  const std::string none = cacheKey(spec, "0.1.0");
  spec.features = someFeatures();
  const std::string drawn = cacheKey(spec, "0.1.0");
  EXPECT_NE(drawn, none);
  input::WorldSpec again = islandSpec();
  again.features = someFeatures();
  EXPECT_EQ(cacheKey(again, "0.1.0"), drawn);
  // Local positions follow from lon/lat and the projection: they are not hashed.
  again.features.mountains[0].position.x = 99.0;
  EXPECT_EQ(cacheKey(again, "0.1.0"), drawn);

  const std::vector<std::function<void(input::Features&)>> changes{
      [](input::Features& f) { f.mountains[0].lonLat.x = 8.94560001; },
      [](input::Features& f) { f.mountains[0].elevation = 2707.0; },
      [](input::Features& f) { f.mountains[0].elevation.reset(); },
      [](input::Features& f) { f.mountains[1].radius = 4500.5; },
      [](input::Features& f) { f.ridges[0].elevation.reset(); },
      [](input::Features& f) {
        f.ridges[1].lonLat.push_back({9.2, 41.86});
      },
      [](input::Features& f) { f.rivers[1].name = "Tavignano"; },
      [](input::Features& f) { std::swap(f.rivers[0], f.rivers[1]); },
      [](input::Features& f) { f.mountains.pop_back(); },
      [](input::Features& f) { f.rivers.clear(); },
  };
  std::set<std::string> keys{none, drawn};
  for (std::size_t i = 0; i < changes.size(); ++i) {
    input::WorldSpec changed = islandSpec();
    changed.features = someFeatures();
    changes[i](changed.features);
    EXPECT_TRUE(keys.insert(cacheKey(changed, "0.1.0")).second) << "change " << i;
  }
}

} // namespace
} // namespace strahler::store
