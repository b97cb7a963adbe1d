// The PMTiles writer's layout: identical contents stored once, run lengths for consecutive
// identical tiles, leaf directories for big archives, no file but the archive left behind.
#include "hilbert_tile_id.h"
#include "pmtiles_writer.h"
#include "result_matchers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
namespace pm = strahler::archive::pmtiles;
using strahler::archive::ArchiveMetadata;
using strahler::archive::PmtilesWriter;
using strahler::archive::TileCoord;
using strahler::archive::tileIdToZxy;
using strahler::archive::zxyToTileId;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(STRAHLER_BINARY_DIR) / "archive_test_scratch" /
                       (name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

ArchiveMetadata metadata() {
  ArchiveMetadata m;
  m.name = "test";
  m.tileFormat = "png";
  m.encoding = "mapbox";
  m.minZoom = 0;
  m.maxZoom = 2;
  m.west = -10.5, m.south = 40.25, m.east = 3.125, m.north = 45.0;
  m.centerLon = -3.6875, m.centerLat = 42.625, m.centerZoom = 1;
  return m;
}

/// The entries of an archive, leaves expanded.
std::vector<pm::Entry> entriesOf(const std::string& file, const pm::Header& h) {
  const auto c = h.internalCompression;
  std::vector<pm::Entry> out;
  const auto root = strahler::test_support::valueOf(pm::decodeDirectory(
      strahler::test_support::valueOf(pm::decompress(file.substr(h.rootOffset, h.rootLength), c))));
  for (const pm::Entry& e : root) {
    if (e.runLength > 0) {
      out.push_back(e);
      continue;
    }
    const auto leaf =
        strahler::test_support::valueOf(pm::decodeDirectory(strahler::test_support::valueOf(
            pm::decompress(file.substr(h.leafOffset + e.offset, e.length), c))));
    out.insert(out.end(), leaf.begin(), leaf.end());
  }
  return out;
}

TEST(PmtilesWriter, StoresIdenticalTilesOnceWithRunLengths) {
  const fs::path dir = scratch("dedup");
  const fs::path path = dir / "a.pmtiles";
  STRAHLER_ASSIGN_OR_ASSERT(auto writer, PmtilesWriter::create(path.string()));
  // Ids 0..20 (zooms 0-2): "sea" everywhere but ids 3 and 9, which are land.
  for (std::uint64_t id = 0; id <= 20; ++id) {
    const std::string bytes = id == 3 ? "land-3" : id == 9 ? "land-9" : "sea";
    STRAHLER_ASSERT_OK(writer->addTile(tileIdToZxy(id), bytes));
  }
  EXPECT_FALSE(writer->addTile(tileIdToZxy(20), "again").ok()) << "ids must ascend";
  STRAHLER_ASSERT_OK(writer->finish(metadata()));
  EXPECT_EQ(writer->stats().tiles, 21u);
  EXPECT_EQ(writer->stats().uniqueTiles, 3u);
  writer.reset();
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1)
      << "the spool file is gone";

  const std::string file = readAll(path);
  STRAHLER_ASSIGN_OR_ASSERT(const pm::Header h, pm::decodeHeader(file));
  EXPECT_EQ(h.addressedTiles, 21u);
  EXPECT_EQ(h.tileContents, 3u);
  EXPECT_EQ(h.tileEntries, 5u); // sea ×3, land-3, sea ×5, land-9, sea ×11
  EXPECT_TRUE(h.clustered);
  EXPECT_EQ(h.tileType, pm::TileType::kPng);
  EXPECT_EQ(h.tileCompression, pm::Compression::kNone);
  EXPECT_EQ(h.internalCompression, pm::Compression::kGzip);
  EXPECT_EQ(h.minZoom, 0);
  EXPECT_EQ(h.maxZoom, 2);
  EXPECT_EQ(h.minLonE7, -105000000);
  EXPECT_EQ(h.maxLatE7, 450000000);
  EXPECT_EQ(h.centerZoom, 1);
  EXPECT_EQ(h.tileDataLength, std::string("sealand-3land-9").size());
  EXPECT_EQ(h.tileDataOffset + h.tileDataLength, file.size());
  const auto entries = entriesOf(file, h);
  ASSERT_EQ(entries.size(), 5u);
  EXPECT_EQ(entries[0].runLength, 3u);
  EXPECT_EQ(entries[2].tileId, 4u);
  EXPECT_EQ(entries[2].runLength, 5u);
  EXPECT_EQ(entries[2].offset, entries[0].offset);
  EXPECT_EQ(file.substr(h.tileDataOffset + entries[3].offset, entries[3].length), "land-9");
  STRAHLER_ASSIGN_OR_ASSERT(
      const std::string meta,
      pm::decompress(file.substr(h.metadataOffset, h.metadataLength), h.internalCompression));
  EXPECT_NE(meta.find("\"encoding\":\"mapbox\""), std::string::npos) << meta;
}

TEST(PmtilesWriter, WritesLeafDirectoriesForManyTiles) {
  const fs::path path = scratch("leaves") / "big.pmtiles";
  STRAHLER_ASSIGN_OR_ASSERT(auto writer, PmtilesWriter::create(path.string()));
  // 40,000 distinct small tiles at zoom 9 (every other id): far more than a 16 KiB root holds.
  const std::uint64_t first = zxyToTileId({9, 0, 0});
  for (std::uint64_t k = 0; k < 40000; ++k)
    ASSERT_TRUE(writer->addTile(tileIdToZxy(first + 2 * k), "tile " + std::to_string(k)).ok());
  STRAHLER_ASSERT_OK(writer->finish(metadata()));
  const std::string file = readAll(path);
  STRAHLER_ASSIGN_OR_ASSERT(const pm::Header h, pm::decodeHeader(file));
  EXPECT_LE(h.rootOffset + h.rootLength, 16384u);
  EXPECT_GT(h.leafLength, 0u);
  const auto entries = entriesOf(file, h);
  ASSERT_EQ(entries.size(), 40000u);
  EXPECT_EQ(entries[12345].tileId, first + 2 * 12345);
  EXPECT_EQ(file.substr(h.tileDataOffset + entries[12345].offset, entries[12345].length),
            "tile 12345");
}

TEST(PmtilesWriter, ReportsAnUnwritablePath) {
  auto writer = PmtilesWriter::create("/nonexistent-folder/x.pmtiles");
  ASSERT_FALSE(writer.ok());
  EXPECT_NE(writer.error().message.find("/nonexistent-folder/x.pmtiles"), std::string::npos);
}

} // namespace
