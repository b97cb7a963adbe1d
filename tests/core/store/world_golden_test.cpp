// Golden payload of format version 2: any change to the encoding shows up here, and must
// come with a new kWorldFormatVersion (old files would otherwise be misread, not refused).
// The params JSON is left out of the golden bytes: it belongs to core/input and changes
// whenever a parameter is added, which the cache key already accounts for.

#include "world_fixtures.h"
#include "world_proto.h"

#include "strahler/input/params.h"
#include "strahler/primitives/quantization.h"
#include "strahler/store/world_file.h"

#include <gtest/gtest.h>

namespace strahler::store {
namespace {

using construction::WorldData;
using network::NodeId;

/// A hand-made world: one triangle island, a mouth with two upstream nodes, three blocks.
WorldData makeTinyWorld() {
  WorldData w;
  w.name = "tiny";
  w.cacheKey = "00112233445566778899aabbccddeeff";
  w.generatorVersion = "1.2.3";
  w.projectionCenter = {8.5, 42.25};
  w.land = {{{{0.0, 0.0}, {3000.0, 0.0}, {1500.125, 2500.5}}, {}}};
  w.network.edgeLength = 1000.0;
  w.network.nodes.resize(3);
  w.network.nodes[0] = {{1500.0, 0.0}, 0.0, NodeId::invalid(), {NodeId(1), NodeId(2)}, 3, 2, 0};
  w.network.nodes[1] = {{1000.0, 875.0}, 12.5, NodeId(0), {}, 2, 1, 0};
  w.network.nodes[2] = {
      {2000.0, 875.125}, primitives::quantize(20.01, 0.01), NodeId(0), {}, 1, 1, 0};
  w.network.mouths = {{NodeId(0), {0.0, 1.0}, false}};
  w.flow = {2.5, 1.0, 1.25};
  w.riverTypes = {primitives::RiverType::kDelta, primitives::RiverType::kStraight,
                  primitives::RiverType::kSinuous};
  w.terrain = {{{1400.0, 300.0}, 400.0, 10.0, {0.25, -0.125}, 5.5, 0.5},
               {{1000.0, 1000.0}, 350.125, 40.25, {0.0, 0.5}, 12.0, 0.625},
               {{2000.0, 1000.0}, 300.0, 55.0, {-0.75, 0.0}, 20.0, 0.3125}};
  primitives::RiverPrimitive river;
  river.curve = {{{1000.0, 875.0}, 12.5}, {{1250.0, 500.0}, 6.0}, {{1500.0, 0.0}, 0.0}};
  river.widthUp = 4.0;
  river.widthDown = 6.5;
  river.depthUp = 0.75;
  river.depthDown = 1.25;
  river.radius = 150.0;
  river.type = primitives::RiverType::kStraight;
  river.node = NodeId(1);
  w.rivers = {river};
  w.blocks = {{0, 1, 0, 0}, {1, 2, 0, 1}, {2, 3, 1, 1}};
  w.stageSeconds = {{"total", 0.5}}; // not stored
  return w;
}

/// `protoc --decode=strahler.v1.World proto/strahler/v1/world.proto` shows it as text.
constexpr std::string_view kGoldenPayloadHex =
    "08021205312e322e331a20303031313232333334343535363637373838393961616262636364646565666622"
    "0474696e7931000000000000214039000000000020454042160a01011201031a070080f702bdbb0122050000"
    "c8b8024a56090000000000408f4012030001021a07c0bb01bf3ec03e220500b06db26d2a0500c413a21f3203"
    "0604023a0304020242068827d00fc4134a030300015201005a0800000000000000006208000000000000f03f"
    "6a0100520a0a0301010112030001005a400a0780af01ff31807d1205c025c057001a0680329d06a1062206d0"
    "0fa22f86172a06cc08940ac00c320680088002ff043a068010ff0fff2f4206ff078028ff1f62320a01031206"
    "807da01fa01f1a06b06def2ebf3e2206c413930aaf092a01403201283a0296014201644a02e0125201005a01"
    "00";

std::string toHex(std::string_view bytes) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out;
  for (const char c : bytes) {
    const auto b = static_cast<unsigned char>(c);
    out.push_back(kDigits[b >> 4]);
    out.push_back(kDigits[b & 0xF]);
  }
  return out;
}

std::string fromHex(std::string_view hex) {
  std::string out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2)
    out.push_back(static_cast<char>(std::stoi(std::string(hex.substr(i, 2)), nullptr, 16)));
  return out;
}

TEST(WorldGolden, EncoderWritesTheVersion2Payload) {
  v1::World message = detail::toProto(makeTinyWorld());
  message.clear_params_json();
  std::string payload;
  ASSERT_TRUE(message.SerializeToString(&payload));
  EXPECT_EQ(toHex(payload), kGoldenPayloadHex)
      << "The world encoding changed: bump kWorldFormatVersion, then update the golden bytes.";
}

TEST(WorldGolden, Version2PayloadReadsBackTheSameWorld) {
  const WorldData tiny = makeTinyWorld();
  v1::World message;
  ASSERT_TRUE(message.ParseFromString(fromHex(kGoldenPayloadHex)));
  message.set_params_json(input::canonicalJson(tiny.params));
  std::string payload;
  ASSERT_TRUE(message.SerializeToString(&payload));
  STRAHLER_ASSIGN_OR_ASSERT(auto decoded, decodeWorld(detail::frame(payload, 2), "golden"));
  EXPECT_TRUE(test_support::worldsEqual(decoded, tiny));
}

TEST(WorldGolden, TimingsDoNotChangeTheBytes) {
  WorldData a = makeTinyWorld(), b = makeTinyWorld();
  a.stageSeconds = {{"network", 1.25}, {"blocks", 0.5}};
  b.stageSeconds = {{"network", 3.0}};
  EXPECT_EQ(encodeWorld(a), encodeWorld(b));
  a.stageSeconds.clear();
  EXPECT_EQ(encodeWorld(a), encodeWorld(b));
}

} // namespace
} // namespace strahler::store
