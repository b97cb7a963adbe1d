// The PMTiles v3 header and directory encodings, and the root/leaf split at 16 KiB.
#include "pmtiles_format.h"
#include "result_matchers.h"

#include <gtest/gtest.h>

#include <random>

namespace {

namespace pm = strahler::archive::pmtiles;

std::vector<pm::Entry> randomEntries(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<pm::Entry> entries;
  std::uint64_t id = 0, offset = 0;
  for (std::size_t i = 0; i < n; ++i) {
    id += 1 + rng() % 50;
    const auto length = static_cast<std::uint32_t>(1 + rng() % 100000);
    const bool repeat = i > 0 && rng() % 4 == 0; // a deduplicated content points back
    entries.push_back({id, repeat ? entries[rng() % i].offset : offset, length,
                       static_cast<std::uint32_t>(1 + rng() % 3)});
    if (repeat)
      entries.back().length = entries[i - 1].length;
    else
      offset += length;
    id += entries.back().runLength;
  }
  return entries;
}

TEST(PmtilesHeader, Is127BytesAndRoundTrips) {
  pm::Header h;
  h.rootOffset = 127;
  h.rootLength = 300;
  h.tileDataOffset = 1u << 31;
  h.tileDataLength = 5'000'000'000ull;
  h.addressedTiles = 12;
  h.clustered = true;
  h.minZoom = 3;
  h.maxZoom = 14;
  h.minLonE7 = -1800000000;
  h.maxLatE7 = 850511287;
  h.centerZoom = 9;
  h.centerLatE7 = -123456789;
  const std::string bytes = pm::encodeHeader(h);
  ASSERT_EQ(bytes.size(), pm::kHeaderBytes);
  EXPECT_EQ(bytes.substr(0, 8), std::string("PMTiles\x03", 8));
  STRAHLER_ASSIGN_OR_ASSERT(auto back, pm::decodeHeader(bytes));
  EXPECT_EQ(pm::encodeHeader(back), bytes);
  EXPECT_EQ(back.tileDataLength, 5'000'000'000ull);
  EXPECT_EQ(back.minLonE7, -1800000000);
  EXPECT_EQ(back.centerLatE7, -123456789);
  EXPECT_FALSE(pm::decodeHeader(bytes.substr(0, 100)).ok());
}

TEST(PmtilesDirectory, RoundTripsWithVarintsAndContiguousOffsets) {
  // Spec example shape: consecutive contents store offset 0 ("contiguous"), others offset + 1.
  const std::vector<pm::Entry> entries = {{0, 0, 100, 1}, {1, 100, 50, 3}, {10, 0, 100, 1}};
  const std::string bytes = pm::encodeDirectory(entries);
  // count, ids delta (0, 1, 9), run lengths, lengths (100 = 0x64, 50, 100), offsets (1, 0, 1).
  EXPECT_EQ(bytes, std::string("\x03\x00\x01\x09\x01\x03\x01\x64\x32\x64\x01\x00\x01", 13));
  STRAHLER_ASSIGN_OR_ASSERT(auto back, pm::decodeDirectory(bytes));
  EXPECT_EQ(back, entries);

  const auto many = randomEntries(20000, 7);
  STRAHLER_ASSIGN_OR_ASSERT(auto again, pm::decodeDirectory(pm::encodeDirectory(many)));
  EXPECT_EQ(again, many);
}

TEST(PmtilesDirectory, RefusesTruncatedBytes) {
  const std::string bytes = pm::encodeDirectory(randomEntries(100, 3));
  for (std::size_t cut : {std::size_t{0}, std::size_t{1}, bytes.size() / 2, bytes.size() - 1})
    EXPECT_FALSE(pm::decodeDirectory(bytes.substr(0, cut)).ok()) << cut;
}

TEST(PmtilesDirectory, GzipRoundTrips) {
  const std::string bytes = pm::encodeDirectory(randomEntries(1000, 5));
  STRAHLER_ASSIGN_OR_ASSERT(auto packed, pm::compress(bytes, pm::Compression::kGzip));
  EXPECT_EQ(packed.substr(0, 2), "\x1f\x8b");
  STRAHLER_ASSIGN_OR_ASSERT(auto unpacked, pm::decompress(packed, pm::Compression::kGzip));
  EXPECT_EQ(unpacked, bytes);
}

/// Every entry reachable from `d`: the root's leaf pointers expanded.
std::vector<pm::Entry> flatten(const pm::Directories& d, pm::Compression c) {
  std::vector<pm::Entry> out;
  const auto root = strahler::test_support::valueOf(
      pm::decodeDirectory(strahler::test_support::valueOf(pm::decompress(d.root, c))));
  for (const pm::Entry& e : root) {
    if (e.runLength > 0) {
      out.push_back(e);
      continue;
    }
    const auto leaf = strahler::test_support::valueOf(pm::decodeDirectory(
        strahler::test_support::valueOf(pm::decompress(d.leaves.substr(e.offset, e.length), c))));
    out.insert(out.end(), leaf.begin(), leaf.end());
  }
  return out;
}

TEST(PmtilesDirectories, SmallDirectoriesStayInTheRoot) {
  const auto entries = randomEntries(500, 11);
  STRAHLER_ASSIGN_OR_ASSERT(auto d, pm::buildDirectories(entries, pm::Compression::kGzip));
  EXPECT_EQ(d.leafCount, 0u);
  EXPECT_TRUE(d.leaves.empty());
  EXPECT_EQ(flatten(d, pm::Compression::kGzip), entries);
}

TEST(PmtilesDirectories, LeavesWhenTheRootWouldExceed16KiB) {
  for (const pm::Compression c : {pm::Compression::kGzip, pm::Compression::kNone}) {
    const auto entries = randomEntries(60000, 13);
    ASSERT_GT(strahler::test_support::valueOf(pm::compress(pm::encodeDirectory(entries), c)).size(),
              pm::kRootLimitBytes);
    STRAHLER_ASSIGN_OR_ASSERT(auto d, pm::buildDirectories(entries, c));
    EXPECT_LE(d.root.size() + pm::kHeaderBytes, 16384u);
    EXPECT_GT(d.leafCount, 1u);
    STRAHLER_ASSIGN_OR_ASSERT(const auto root, pm::decodeDirectory(strahler::test_support::valueOf(
                                                   pm::decompress(d.root, c))));
    for (const pm::Entry& e : root)
      EXPECT_EQ(e.runLength, 0u) << "the root holds only leaf pointers";
    EXPECT_EQ(flatten(d, c), entries);
  }
}

} // namespace
