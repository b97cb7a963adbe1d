// The MBTiles writer as far as it can be seen without SQLite: its figures, the file it leaves
// (one SQLite database, no journal beside it) and its errors. The tables are read by Python's
// sqlite3 in tests/cli/check_mbtiles.py.
#include "mbtiles_writer.h"
#include "result_matchers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using strahler::archive::ArchiveMetadata;
using strahler::archive::MbtilesWriter;

TEST(MbtilesWriter, StoresIdenticalTilesOnceAndLeavesOneDatabaseFile) {
  const fs::path dir = fs::path(STRAHLER_BINARY_DIR) / "archive_test_scratch" /
                       ("mbtiles-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path path = dir / "a.mbtiles";
  STRAHLER_ASSIGN_OR_ASSERT(auto writer, MbtilesWriter::create(path.string()));
  for (std::uint32_t x = 0; x < 4; ++x)
    STRAHLER_ASSERT_OK(writer->addTile({2, x, 1}, x == 2 ? "land" : "sea"));
  ArchiveMetadata m;
  m.name = "test";
  m.tileFormat = "png";
  m.encoding = "terrarium";
  m.extra = {{"seed", "7"}};
  STRAHLER_ASSERT_OK(writer->finish(m));
  EXPECT_EQ(writer->stats().tiles, 4u);
  EXPECT_EQ(writer->stats().uniqueTiles, 2u);
  EXPECT_EQ(writer->stats().tileBytes, 7u);
  EXPECT_FALSE(writer->addTile({3, 0, 0}, "late").ok());
  EXPECT_FALSE(writer->finish(m).ok());
  writer.reset();
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  char magic[16] = {};
  std::ifstream(path, std::ios::binary).read(magic, sizeof magic);
  EXPECT_EQ(std::string(magic, 16), std::string("SQLite format 3\0", 16));
}

TEST(MbtilesWriter, ReportsAnUnwritablePath) {
  auto writer = MbtilesWriter::create("/nonexistent-folder/x.mbtiles");
  ASSERT_FALSE(writer.ok());
  EXPECT_NE(writer.error().message.find("/nonexistent-folder/x.mbtiles"), std::string::npos);
}

} // namespace
