// The erosion's residual in the world file: round trips, empty chunks, format versions, and
// damaged chunks refused with a message naming the fault.

#include "world_fixtures.h"
#include "world_proto.h"

#include "strahler/base/random.h"
#include "strahler/store/world_file.h"

#include <gtest/gtest.h>

#include <cstring>

namespace strahler::store {
namespace {

using base::ErrorCode;
using construction::ReliefResidual;
using test_support::failsWith;
using test_support::makeSmallWorld;

/// A 192 × 128 residual at 60 m from (−64, −64): smooth values in the middle chunks, zeros
/// in the others, a few extremes.
ReliefResidual makeResidual() {
  ReliefResidual r;
  r.spacing = 60.0;
  r.column0 = -64;
  r.row0 = -64;
  r.columns = 192;
  r.rows = 128;
  r.quanta.assign(static_cast<std::size_t>(r.columns * r.rows), 0);
  base::Rng rng(4);
  for (int y = 0; y < r.rows; ++y)
    for (int x = 64; x < 128; ++x) // the middle column of chunks
      r.quanta[static_cast<std::size_t>(y * r.columns + x)] = static_cast<std::int16_t>(
          300.0 * std::sin(x * 0.1) * std::cos(y * 0.07) + rng.uniform(-5.0, 5.0));
  r.quanta[64] = 32767;
  r.quanta[65] = -32767;
  return r;
}

construction::WorldData erodedWorld() {
  construction::WorldData world = makeSmallWorld();
  world.relief = makeResidual();
  return world;
}

std::string payloadOf(const v1::World& message) {
  std::string payload;
  EXPECT_TRUE(message.SerializeToString(&payload));
  return payload;
}

TEST(ReliefCodec, RoundTripsExactlyInFormatThree) {
  const construction::WorldData world = erodedWorld();
  const std::string bytes = encodeWorld(world);
  std::uint32_t version = 0;
  std::memcpy(&version, bytes.data() + 14, 4); // little-endian hosts (x86, ARM)
  EXPECT_EQ(version, kWorldFormatVersion);
  STRAHLER_ASSIGN_OR_ASSERT(auto decoded, decodeWorld(bytes, "eroded"));
  const construction::WorldData& back = decoded;
  EXPECT_EQ(back.relief, world.relief);
  EXPECT_EQ(encodeWorld(back), bytes);
}

TEST(ReliefCodec, AllZeroChunksAreStoredEmpty) {
  const v1::World message = detail::toProto(erodedWorld());
  ASSERT_EQ(message.relief().chunks_size(), 3 * 2);
  for (int k = 0; k < 6; ++k)
    EXPECT_EQ(message.relief().chunks(k).empty(), k % 3 != 1) << "chunk " << k;
}

TEST(ReliefCodec, AWorldWithoutResidualKeepsFormatTwo) {
  const std::string bytes = encodeWorld(makeSmallWorld());
  std::uint32_t version = 0;
  std::memcpy(&version, bytes.data() + 14, 4);
  EXPECT_EQ(version, kWorldFormatVersionWithoutRelief);
  EXPECT_FALSE(detail::toProto(makeSmallWorld()).has_relief());
}

/// Decodes the eroded world's message after `mutate`, framed with a valid header and CRC.
base::Result<construction::WorldData> decodeMutated(const std::function<void(v1::World&)>& mutate) {
  v1::World message = detail::toProto(erodedWorld());
  mutate(message);
  return decodeWorld(detail::frame(payloadOf(message), kWorldFormatVersion), "bad.world");
}

TEST(ReliefCodec, DamagedResidualsAreRefused) {
  EXPECT_TRUE(failsWith(decodeMutated([](v1::World& m) { m.set_format_version(2); }),
                        ErrorCode::kCorrupt, "an erosion residual in a world of format version 2"));
  EXPECT_TRUE(failsWith(decodeMutated([](v1::World& m) { m.mutable_relief()->set_spacing(0.0); }),
                        ErrorCode::kCorrupt, "relief: spacing"));
  EXPECT_TRUE(failsWith(decodeMutated([](v1::World& m) { m.mutable_relief()->set_column0(-63); }),
                        ErrorCode::kCorrupt, "is not a non-empty whole number of chunks"));
  EXPECT_TRUE(failsWith(decodeMutated([](v1::World& m) { m.mutable_relief()->set_chunk_size(32); }),
                        ErrorCode::kCorrupt, "chunk size 32, expected 64"));
  EXPECT_TRUE(failsWith(decodeMutated([](v1::World& m) { m.mutable_relief()->set_rows(64); }),
                        ErrorCode::kCorrupt, "6 chunks, expected 3"));
  EXPECT_TRUE(failsWith(decodeMutated([](v1::World& m) {
                          m.mutable_relief()->set_columns(1u << 20);
                          m.mutable_relief()->set_rows(1u << 12);
                        }),
                        ErrorCode::kCorrupt, "more than the limit"));
  // A chunk's stream truncated, or with a byte flipped: zlib's checksum or the varints say so.
  EXPECT_TRUE(failsWith(decodeMutated([](v1::World& m) {
                          std::string& c = *m.mutable_relief()->mutable_chunks(1);
                          c.resize(c.size() / 2);
                        }),
                        ErrorCode::kCorrupt, "chunk 1: not a valid zlib stream"));
  base::Rng rng(8);
  for (int trial = 0; trial < 200; ++trial) {
    auto decoded = decodeMutated([&](v1::World& m) {
      std::string& c = *m.mutable_relief()->mutable_chunks(4);
      c[rng.below(static_cast<std::uint32_t>(c.size()))] ^= static_cast<char>(1 + rng.below(255));
    });
    ASSERT_FALSE(decoded.ok()) << "trial " << trial;
    ASSERT_EQ(decoded.error().code, ErrorCode::kCorrupt);
  }
}

} // namespace
} // namespace strahler::store
