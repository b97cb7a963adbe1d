// `strahler export` run as a user runs it: deterministic archives for any thread count, the
// server's exact tile bytes, nothing left behind when interrupted or refused.
#include "hilbert_tile_id.h"
#include "pmtiles_format.h"
#include "program_run.h"
#include "result_matchers.h"
#include "serve_process.h"
#include "test_client.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
namespace pm = strahler::archive::pmtiles;
using namespace std::chrono_literals;
using strahler::test_support::ProcessRun;
using strahler::test_support::readWholeFile;

fs::path scratchDir() {
  return strahler::test_support::processScratchDir(
      fs::path(STRAHLER_BINARY_DIR) / "cli_test_scratch", "export");
}

ProcessRun strahler(const std::string& args) {
  return strahler::test_support::runProgram(STRAHLER_EXECUTABLE, args, scratchDir());
}

/// The default island as a world file, generated once per test process.
const fs::path& islandWorld() {
  static const fs::path path = [] {
    const fs::path p = scratchDir() / "island.world";
    const ProcessRun run = strahler("generate --quiet -o " + p.string());
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return p;
  }();
  return path;
}

/// An empty folder of its own for one test's outputs.
fs::path outputDir(const std::string& name) {
  const fs::path dir = scratchDir() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  return names;
}

/// The bytes of tile z/x/y in a PMTiles archive without leaf directories ("" if absent).
std::string pmtilesTile(const std::string& file, int z, std::uint32_t x, std::uint32_t y) {
  const pm::Header h = strahler::test_support::valueOf(pm::decodeHeader(file));
  const auto root =
      strahler::test_support::valueOf(pm::decodeDirectory(strahler::test_support::valueOf(
          pm::decompress(file.substr(h.rootOffset, h.rootLength), h.internalCompression))));
  const std::uint64_t id = strahler::archive::zxyToTileId({z, x, y});
  for (const pm::Entry& e : root)
    if (e.runLength > 0 && e.tileId <= id && id < e.tileId + e.runLength)
      return file.substr(h.tileDataOffset + e.offset, e.length);
  return {};
}

TEST(ExportCommand, WritesTheSameArchiveForOneAndTwoThreads) {
  const fs::path dir = outputDir("determinism");
  for (const char* ext : {"pmtiles", "mbtiles"}) {
    std::string archives[2];
    for (int threads = 1; threads <= 2; ++threads) {
      const fs::path out = dir / ("t" + std::to_string(threads) + "." + ext);
      const ProcessRun run =
          strahler("export " + islandWorld().string() + " --zooms 0-11 --threads " +
                   std::to_string(threads) + " -o " + out.string());
      ASSERT_EQ(run.exitCode, 0) << run.err;
      archives[threads - 1] = readWholeFile(out);
    }
    EXPECT_GT(archives[0].size(), 10000u) << ext;
    EXPECT_TRUE(archives[0] == archives[1]) << ext << ": archives differ between thread counts";
  }
}

TEST(ExportCommand, PrintsASummary) {
  const fs::path out = outputDir("summary") / "a.pmtiles";
  const ProcessRun run =
      strahler("export " + islandWorld().string() + " --zooms 3-9 -o " + out.string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  for (const char* part : {"exported ", " tiles (", " unique) to ", " bytes in ", " tiles/s"})
    EXPECT_NE(run.err.find(part), std::string::npos) << part << " in: " << run.err;
  const ProcessRun quiet =
      strahler("export " + islandWorld().string() + " --quiet --zooms 3-9 -o " + out.string());
  ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
}

TEST(ExportCommand, ArchiveTilesAreTheBytesTheServerSends) {
  const fs::path out = outputDir("served") / "a.pmtiles";
  const ProcessRun run = strahler("export " + islandWorld().string() +
                                  " --zooms 10-12 --tile terrarium -o " + out.string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string archive = readWholeFile(out);
  strahler::test_support::ServeProcess serve(
      {STRAHLER_EXECUTABLE, "serve", islandWorld().string(), "--quiet", "--port", "0"},
      "STRAHLER_CACHE_DIR=" + (scratchDir() / "cache").string());
  ASSERT_GT(serve.pid(), 0);
  const std::uint16_t port = serve.readPort();
  ASSERT_NE(port, 0);
  // Sea (the corners of the island's box) and land (its middle), at each zoom.
  const struct {
    int z;
    std::uint32_t x, y;
  } tiles[] = {{10, 433, 372},   {10, 434, 373},   {11, 866, 745},
               {12, 1732, 1491}, {12, 1736, 1493}, {12, 1740, 1495}};
  for (const auto& t : tiles) {
    const std::string path = "/worlds/island/tiles/" + std::to_string(t.z) + "/" +
                             std::to_string(t.x) + "/" + std::to_string(t.y) +
                             ".png?encoding=terrarium";
    const auto response =
        strahler::http::test::fetch(port, strahler::http::test::getRequest(path), 30s);
    ASSERT_TRUE(response && response->status == 200) << path;
    const std::string stored = pmtilesTile(archive, t.z, t.x, t.y);
    EXPECT_FALSE(stored.empty()) << path << " is not in the archive";
    EXPECT_TRUE(stored == response->body) << path << ": archive and server bytes differ";
  }
}

TEST(ExportCommand, ArchivesColourReliefTilesAsStrahlerTileWritesThem) {
  const fs::path dir = outputDir("relief");
  const fs::path out = dir / "a.pmtiles";
  const ProcessRun run = strahler("export " + islandWorld().string() +
                                  " --zooms 11-12 --tile relief -o " + out.string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string archive = readWholeFile(out);
  const pm::Header h = strahler::test_support::valueOf(pm::decodeHeader(archive));
  EXPECT_EQ(h.tileType, pm::TileType::kPng);
  const std::string metadata = strahler::test_support::valueOf(
      pm::decompress(archive.substr(h.metadataOffset, h.metadataLength), h.internalCompression));
  EXPECT_NE(metadata.find("colour relief"), std::string::npos) << metadata;
  EXPECT_EQ(metadata.find("\"encoding\""), std::string::npos) << "not a heightmap: " << metadata;
  const fs::path tile = dir / "t.png";
  const ProcessRun one = strahler("tile " + islandWorld().string() +
                                  " --z 12 --x 1736 --y 1494 --format relief -o " + tile.string());
  ASSERT_EQ(one.exitCode, 0) << one.err;
  const std::string stored = pmtilesTile(archive, 12, 1736, 1494);
  EXPECT_FALSE(stored.empty());
  EXPECT_TRUE(stored == readWholeFile(tile)) << "archive and strahler tile bytes differ";
}

TEST(ExportCommand, ArchivesLayerTilesAsStrahlerTileLayerWritesThem) {
  const fs::path dir = outputDir("layer");
  const fs::path out = dir / "a.pmtiles";
  const std::string layer = " --layer hillshade --azimuth 270 --altitude 30";
  const ProcessRun run = strahler("export " + islandWorld().string() + " --zooms 11-12" + layer +
                                  " -o " + out.string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string archive = readWholeFile(out);
  const pm::Header h = strahler::test_support::valueOf(pm::decodeHeader(archive));
  EXPECT_EQ(h.tileType, pm::TileType::kPng);
  EXPECT_EQ(h.tileCompression, pm::Compression::kNone);
  const std::string metadata = strahler::test_support::valueOf(
      pm::decompress(archive.substr(h.metadataOffset, h.metadataLength), h.internalCompression));
  for (const char* part :
       {"\"layer\":\"hillshade\"", "\"layerQuery\":\"azimuth=270&altitude=30\"",
        "\"layerEncoding\":\"strahler hillshade: 8-bit grey PNG", "\"format\":\"png\""})
    EXPECT_NE(metadata.find(part), std::string::npos) << part << " in " << metadata;
  EXPECT_EQ(metadata.find("\"encoding\""), std::string::npos) << "not a heightmap: " << metadata;
  const fs::path tile = dir / "t.png";
  const ProcessRun one = strahler("tile " + islandWorld().string() + " --z 12 --x 1736 --y 1494" +
                                  layer + " -o " + tile.string());
  ASSERT_EQ(one.exitCode, 0) << one.err;
  const std::string stored = pmtilesTile(archive, 12, 1736, 1494);
  EXPECT_FALSE(stored.empty());
  EXPECT_TRUE(stored == readWholeFile(tile)) << "archive and strahler tile --layer bytes differ";
}

/// Starts an export that runs for many seconds, sends `signal` once its temporary file exists,
/// and checks that the process dies by it leaving no file behind.
void interruptExport(int signal, const std::string& ext) {
  const fs::path dir = outputDir("interrupt-" + std::to_string(signal) + ext);
  const fs::path out = dir / ("big." + ext);
  strahler::test_support::ServeProcess run({STRAHLER_EXECUTABLE, "export", islandWorld().string(),
                                            "--zooms", "0-16", "--threads", "1", "--quiet", "-o",
                                            out.string()},
                                           "");
  ASSERT_GT(run.pid(), 0);
  const fs::path temporary = out.string() + ".tmp." + std::to_string(run.pid());
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (!fs::exists(temporary) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(20ms);
  ASSERT_TRUE(fs::exists(temporary)) << "no " << temporary << " within 60 s";
  std::this_thread::sleep_for(500ms); // some tiles are written
  ::kill(run.pid(), signal);
  const auto status = run.waitUntil(std::chrono::steady_clock::now() + 20s);
  ASSERT_TRUE(status) << "export still running 20 s after the signal";
  EXPECT_TRUE(WIFSIGNALED(*status) && WTERMSIG(*status) == signal) << "wait status " << *status;
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{}) << "left behind after the signal";
}

TEST(ExportCommand, SigtermLeavesNoArchiveAndNoTemporaryFile) {
  interruptExport(SIGTERM, "pmtiles");
  interruptExport(SIGTERM, "mbtiles");
}

TEST(ExportCommand, SigintLeavesNoArchiveAndNoTemporaryFile) {
  interruptExport(SIGINT, "pmtiles");
}

TEST(ExportCommand, RefusesBadInputWithAPreciseMessageAndLeavesNothing) {
  const fs::path dir = outputDir("bad");
  const std::string world = islandWorld().string();
  const std::string out = " -o " + (dir / "a.pmtiles").string();
  std::ofstream(dir.parent_path() / "damaged.world") << "not a world file";
  const struct {
    std::string args;
    int exitCode;
    std::string message;
  } cases[] = {
      {world + " --zooms 5-3" + out, 2, "--zooms '5-3': the first zoom is above the last"},
      {world + " --zooms 0-19" + out, 2, "--zooms '0-19': zoom outside 0..18"},
      {world + " --zooms 3-x" + out, 2, "--zooms '3-x': not a zoom range"},
      {world + " --zooms 0-3 --bbox 1,2,3" + out, 2, "expected four numbers W,S,E,N"},
      {world + " --zooms 0-3 --bbox 10,10,5,20" + out, 2, "W must be less than E"},
      {world + " --zooms 0-3 --bbox 0,0,200,10" + out, 2, "longitudes must be in [-180, 180]"},
      // The box is fine as a command line; it does not fit the world read (exit 1).
      {world + " --zooms 0-3 --bbox 100,10,110,20" + out, 1,
       "--bbox 100.00000,10.00000,110.00000,20.00000 does not overlap the world (bounds "},
      {world + " --zooms 0-3 --format zip" + out, 2, "unknown archive format 'zip'"},
      {world + " --zooms 0-3 --tile glb" + out, 2, "--tile glb: archives hold PNG tiles"},
      {world + " --zooms 0-3 --tile webm" + out, 2, "unknown tile format 'webm'"},
      {world + " --zooms 0-3 --scheme local" + out, 2, "archives hold Web Mercator tiles"},
      {world + " --zooms 0-3 --layer nope" + out, 2,
       "unknown layer 'nope' (layers: slope, aspect, illumination, hillshade, humidity, "
       "sediment, vegetation, water)"},
      {world + " --zooms 0-3 --layer slope --tile png" + out, 2,
       "--layer slope and --tile png: a layer archive holds the layer's grey PNGs; give one of "
       "them"},
      {world + " --zooms 0-3 --species bush" + out, 2, "--species needs --layer"},
      {world + " --zooms 0-3 --layer slope --species bush" + out, 2,
       "'species' is a parameter of the vegetation layer only, not of slope"},
      {world + " --zooms 0-3 --layer vegetation --species oak" + out, 2, "unknown species 'oak'"},
      {world + " --zooms 0-3 --layer hillshade --azimuth 400" + out, 2,
       "azimuth must be in [0, 360) degrees"},
      {world + " --zooms 0-3 --size 2000" + out, 2, "option '--size' must be an integer in [16"},
      {world + " --zooms 0-3 -o " + (dir / "a.zip").string(), 2,
       "cannot tell the archive format from"},
      {world + " --zooms 0-3", 2, "missing -o"},
      {world + " --zooms 0-3 --bogus 1" + out, 2, "unknown option '--bogus'"},
      {world + " --zooms 0-3 -o /nonexistent-folder/a.pmtiles", 1,
       "cannot write '/nonexistent-folder/a.pmtiles': no folder"},
      {world + " --zooms 0-3 --format pmtiles -o " + dir.string(), 1, "it is a folder"},
      {(dir / "missing.world").string() + " --zooms 0-3" + out, 1, "missing.world"},
      {(dir.parent_path() / "damaged.world").string() + " --zooms 0-3" + out, 1, "damaged.world"},
      {world + " --zooms 0-18 --max-tiles 1000" + out, 1,
       "tiles, more than --max-tiles 1000: lower the last zoom, give a smaller --bbox, or "
       "raise --max-tiles"},
      {world + " --zooms 0-12 --max-tiles 10" + out, 1, "are 77 tiles, more than --max-tiles 10"},
  };
  for (const auto& c : cases) {
    const ProcessRun run = strahler("export " + c.args);
    EXPECT_EQ(run.exitCode, c.exitCode) << c.args << "\n" << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << c.args << "\n" << run.err;
    EXPECT_EQ(run.err.find("Segmentation"), std::string::npos) << run.err;
  }
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{});
}

TEST(ExportCommand, IsInTheUsageText) {
  const ProcessRun run = strahler("help");
  EXPECT_NE(run.out.find("export"), std::string::npos);
  const ProcessRun help = strahler("export --help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("--zooms A-B"), std::string::npos);
  EXPECT_NE(help.out.find("--layer NAME"), std::string::npos);
}

} // namespace
