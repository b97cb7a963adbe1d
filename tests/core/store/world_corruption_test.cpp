// Damaged world files: every truncation and bit flip is caught, and payloads that are valid
// protobuf but inconsistent are refused with a message naming the fault.

#include "world_fixtures.h"
#include "world_proto.h"

#include "strahler/base/random.h"
#include "strahler/store/world_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>

namespace strahler::store {
namespace {

using base::ErrorCode;
using test_support::failsWith;
using test_support::makeLargeWorld;
using test_support::makeSmallWorld;

const std::string& smallBytes() {
  static const std::string bytes = encodeWorld(makeSmallWorld());
  return bytes;
}

const std::string& largeBytes() {
  static const std::string bytes = encodeWorld(makeLargeWorld(300.0));
  return bytes;
}

/// Offsets spread over [0, size): the first and last 64, and `count` evenly between.
std::vector<std::size_t> sampleOffsets(std::size_t size, std::size_t count) {
  std::vector<std::size_t> offsets;
  for (std::size_t i = 0; i < 64 && i < size; ++i)
    offsets.push_back(i);
  for (std::size_t k = 0; k < count; ++k)
    offsets.push_back(64 + k * (size - 128) / count);
  for (std::size_t i = size - 64; i < size; ++i)
    offsets.push_back(i);
  return offsets;
}

TEST(WorldCorruption, EveryTruncationOfASmallWorldIsRefused) {
  const std::string& bytes = smallBytes();
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    auto decoded = decodeWorld(std::string_view(bytes).substr(0, n), "cut");
    ASSERT_FALSE(decoded.ok()) << "truncated to " << n << " bytes";
    ASSERT_EQ(decoded.error().code, ErrorCode::kCorrupt) << decoded.error().message;
  }
  EXPECT_TRUE(failsWith(decodeWorld(bytes.substr(0, 10), "cut"), ErrorCode::kCorrupt,
                        "world file 'cut': truncated: 10 bytes"));
  EXPECT_TRUE(failsWith(decodeWorld(bytes.substr(0, bytes.size() - 1), "cut"), ErrorCode::kCorrupt,
                        "(truncated or extended)"));
}

TEST(WorldCorruption, SampledTruncationsOfALargeWorldAreRefused) {
  const std::string& bytes = largeBytes();
  for (const std::size_t n : sampleOffsets(bytes.size(), 300)) {
    auto decoded = decodeWorld(std::string_view(bytes).substr(0, n), "cut");
    ASSERT_FALSE(decoded.ok()) << "truncated to " << n << " bytes";
    ASSERT_EQ(decoded.error().code, ErrorCode::kCorrupt);
  }
}

TEST(WorldCorruption, TrailingBytesAreRefused) {
  EXPECT_TRUE(failsWith(decodeWorld(smallBytes() + "x", "long"), ErrorCode::kCorrupt,
                        "(truncated or extended)"));
}

TEST(WorldCorruption, EveryBitFlipOfASmallWorldIsDetected) {
  std::string bytes = smallBytes();
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    for (int bit = 0; bit < 8; ++bit) {
      bytes[i] = static_cast<char>(bytes[i] ^ (1 << bit));
      auto decoded = decodeWorld(bytes, "flipped");
      bytes[i] = static_cast<char>(bytes[i] ^ (1 << bit));
      ASSERT_FALSE(decoded.ok()) << "bit " << bit << " of byte " << i;
      ASSERT_EQ(decoded.error().code, ErrorCode::kCorrupt);
    }
  }
  std::string flipped = bytes;
  flipped[kWorldHeaderBytes + 5] = static_cast<char>(flipped[kWorldHeaderBytes + 5] ^ 0x10);
  EXPECT_TRUE(failsWith(decodeWorld(flipped, "flipped"), ErrorCode::kCorrupt,
                        "world file 'flipped': checksum mismatch"));
}

TEST(WorldCorruption, SampledBitFlipsOfALargeWorldAreDetected) {
  std::string bytes = largeBytes();
  base::Rng rng(11);
  for (const std::size_t i : sampleOffsets(bytes.size(), 500)) {
    const int mask = 1 << rng.below(8);
    bytes[i] = static_cast<char>(bytes[i] ^ mask);
    auto decoded = decodeWorld(bytes, "flipped");
    bytes[i] = static_cast<char>(bytes[i] ^ mask);
    ASSERT_FALSE(decoded.ok()) << "byte " << i;
    ASSERT_EQ(decoded.error().code, ErrorCode::kCorrupt);
  }
}

TEST(WorldCorruption, WrongMagicIsRefused) {
  std::string bytes = smallBytes();
  bytes[0] = 'X';
  EXPECT_TRUE(failsWith(decodeWorld(bytes, "png"), ErrorCode::kCorrupt,
                        "world file 'png': not a strahler world file"));
}

TEST(WorldCorruption, OtherFormatVersionIsNamed) {
  STRAHLER_ASSIGN_OR_ASSERT(auto payload, detail::unframe(smallBytes(), "w"));
  const std::string future = detail::frame(payload, 7);
  EXPECT_TRUE(failsWith(decodeWorld(future, "old.world"), ErrorCode::kCorrupt,
                        "world file 'old.world' has format version 7, this strahler reads "
                        "versions 2 and 3"));
}

TEST(WorldCorruption, GarbagePayloadWithAValidChecksumIsRefused) {
  EXPECT_TRUE(failsWith(decodeWorld(detail::frame("\xff\xff\xff\xff", kWorldFormatVersion), "g"),
                        ErrorCode::kCorrupt, "not a valid strahler.v1.World protobuf message"));
  base::Rng rng(3);
  for (int trial = 0; trial < 3000; ++trial) {
    std::string payload(rng.below(200), '\0');
    for (char& c : payload)
      c = static_cast<char>(rng.below(256));
    auto decoded = decodeWorld(detail::frame(payload, kWorldFormatVersion), "random");
    ASSERT_FALSE(decoded.ok());
    ASSERT_EQ(decoded.error().code, ErrorCode::kCorrupt);
  }
}

/// Encodes the small world's message after `mutate`, with a valid header and checksum.
base::Result<construction::WorldData> decodeMutated(const std::function<void(v1::World&)>& mutate) {
  v1::World message = detail::toProto(makeSmallWorld());
  mutate(message);
  std::string payload;
  EXPECT_TRUE(message.SerializeToString(&payload));
  return decodeWorld(detail::frame(payload, kWorldFormatVersion), "bad.world");
}

struct Inconsistency {
  const char* name;
  std::function<void(v1::World&)> mutate;
  const char* message;
};

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::int64_t kMaxInt64 = std::numeric_limits<std::int64_t>::max();
constexpr std::uint32_t kMaxUint32 = std::numeric_limits<std::uint32_t>::max();

const std::vector<Inconsistency>& inconsistencies() {
  static const std::vector<Inconsistency> cases = {
      {"block terrain counts do not sum",
       [](v1::World& m) {
         m.mutable_blocks()->set_terrain_count(0, m.blocks().terrain_count(0) + 1);
       },
       "terrain.x has"},
      {"block river counts do not sum",
       [](v1::World& m) { m.mutable_blocks()->set_river_count(0, m.blocks().river_count(0) + 1); },
       "rivers.point_count has"},
      {"one block too many", [](v1::World& m) { m.mutable_blocks()->add_river_count(1); },
       "blocks.river_count has 13 values, expected 12 (one block per node)"},
      {"huge block count",
       [](v1::World& m) { m.mutable_blocks()->set_terrain_count(3, kMaxUint32); },
       "values, expected 4294967" /* 2^32 - 1 + the other counts */},
      {"parent before node 0", [](v1::World& m) { m.mutable_network()->set_parent_offset(5, 100); },
       "node 5 has parent offset 100, which points before node 0"},
      {"parentless node that is no mouth",
       [](v1::World& m) { m.mutable_network()->set_parent_offset(1, 0); },
       "node 1 has no parent but is not a mouth"},
      {"mouth out of range", [](v1::World& m) { m.mutable_network()->set_mouth_node(0, 9999); },
       "mouth 0 names node 9999 of 12"},
      {"mouth with a parent", [](v1::World& m) { m.mutable_network()->set_mouth_node(1, 1); },
       "mouth 1 names node 1, which has a parent"},
      {"two mouths on one node",
       [](v1::World& m) { m.mutable_network()->set_mouth_node(1, m.network().mouth_node(0)); },
       "as mouth 0 does"},
      {"mouth columns differ", [](v1::World& m) { m.mutable_network()->add_mouth_on_lake(true); },
       "network.mouth_on_lake has 3 values, expected 2"},
      {"non-finite mouth direction",
       [](v1::World& m) { m.mutable_network()->set_mouth_inward_x(0, kNaN); },
       "mouth 0 has a non-finite inward direction"},
      {"per-node column too short",
       [](v1::World& m) { m.mutable_network()->mutable_flow()->RemoveLast(); },
       "network.flow has 11 values, expected 12 (one per node)"},
      {"node type out of range", [](v1::World& m) { m.mutable_network()->set_river_type(2, 4); },
       "network.river_type value 2 is river type 4, the largest is 3"},
      {"river type out of range", [](v1::World& m) { m.mutable_rivers()->set_type(0, 9); },
       "rivers.type value 0 is river type 9"},
      {"curve of one point", [](v1::World& m) { m.mutable_rivers()->set_point_count(0, 1); },
       "river primitive 0 has 1 curve points, fewer than 2"},
      {"huge curve point count",
       [](v1::World& m) { m.mutable_rivers()->set_point_count(0, kMaxUint32); }, "rivers.x has"},
      {"river node outside the network",
       [](v1::World& m) { m.mutable_rivers()->set_node(0, 1000); },
       "river primitive 0 names a node outside the 12 of the network"},
      {"huge ring count",
       [](v1::World& m) { m.mutable_land()->set_polygon_ring_counts(0, kMaxUint32); },
       "land.ring_vertex_counts has 3 values, expected 4294967296"},
      {"polygon without rings",
       [](v1::World& m) { m.mutable_land()->set_polygon_ring_counts(1, 0); },
       "land polygon 1 has no ring"},
      {"ring of two vertices", [](v1::World& m) { m.mutable_land()->set_ring_vertex_counts(2, 2); },
       "land ring 2 has 2 vertices, fewer than 3"},
      {"delta overflow", [](v1::World& m) { m.mutable_terrain()->set_x(1, kMaxInt64); },
       "terrain.x value 1 is out of range"},
      {"value beyond 2^50",
       [](v1::World& m) { m.mutable_network()->set_elevation(0, std::int64_t{1} << 51); },
       "network.elevation value 0 is out of range"},
      {"terrain columns differ",
       [](v1::World& m) { m.mutable_terrain()->mutable_roughness()->RemoveLast(); },
       "terrain.roughness has"},
      {"NaN projection", [](v1::World& m) { m.set_projection_lon(kNaN); },
       "is not a longitude and latitude"},
      {"NaN edge length", [](v1::World& m) { m.mutable_network()->set_edge_length(kNaN); },
       "the edge length is not finite"},
      {"infinite stage time (files before timings were left out had them)",
       [](v1::World& m) { m.add_stage_times()->set_seconds(kInfinity); },
       "stage time 0 is not finite"},
      {"invalid params", [](v1::World& m) { m.set_params_json(R"({"kappa": -1})"); },
       "the stored params are invalid: "},
      {"payload version differs", [](v1::World& m) { m.set_format_version(1); },
       "the payload says format version 1, not 2 or 3"},
  };
  return cases;
}

TEST(WorldCorruption, InconsistentPayloadsAreRefusedWithAPreciseMessage) {
  STRAHLER_ASSERT_OK(decodeMutated([](v1::World&) {}));
  for (const Inconsistency& c : inconsistencies()) {
    const auto decoded = decodeMutated(c.mutate);
    EXPECT_TRUE(failsWith(decoded, ErrorCode::kCorrupt, c.message)) << c.name;
    if (!decoded.ok()) {
      EXPECT_EQ(decoded.error().message.rfind("world file 'bad.world': ", 0), 0u) << c.name;
    }
  }
}

TEST(WorldCorruption, DamagedPayloadsWithValidChecksumsNeverCrash) {
  // Whatever the reader accepts must be a valid world: the writer (which asserts every
  // invariant) writes it back and the reader returns it unchanged.
  STRAHLER_ASSIGN_OR_ASSERT(auto payload, detail::unframe(smallBytes(), "w"));
  base::Rng rng(17);
  int accepted = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string damaged(payload);
    for (std::uint32_t k = 0, n = 1 + rng.below(3); k < n; ++k)
      damaged[rng.below(static_cast<std::uint32_t>(damaged.size()))] =
          static_cast<char>(rng.below(256));
    auto decoded = decodeWorld(detail::frame(damaged, kWorldFormatVersion), "damaged");
    if (!decoded.ok()) {
      ASSERT_EQ(decoded.error().code, ErrorCode::kCorrupt);
      continue;
    }
    ++accepted;
    STRAHLER_ASSIGN_OR_ASSERT(auto again, decodeWorld(encodeWorld(decoded.value()), "again"));
    ASSERT_TRUE(test_support::worldsEqual(again, decoded.value()));
  }
  std::cout << "[ damaged  ] " << accepted << " of 3000 damaged payloads still decoded\n";
}

} // namespace
} // namespace strahler::store
