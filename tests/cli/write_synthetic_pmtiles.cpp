// Writes a PMTiles archive too big for a 16 KiB root directory (40,000 distinct tiles at zoom 9,
// every other tile id, plus runs of one repeated tile), so that tests/node/check_pmtiles_leaves.mjs
// can read its leaf directories with the npm pmtiles library. Tile k holds "tile k".
// Usage: write_synthetic_pmtiles FILE
#include "hilbert_tile_id.h"
#include "pmtiles_writer.h"

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  using namespace strahler::archive;
  if (argc != 2) {
    std::fputs("usage: write_synthetic_pmtiles FILE\n", stderr);
    return 2;
  }
  auto writer = PmtilesWriter::create(argv[1]);
  if (!writer) {
    std::fprintf(stderr, "%s\n", writer.error().message.c_str());
    return 1;
  }
  const std::uint64_t first = zxyToTileId({9, 0, 0});
  for (std::uint64_t k = 0; k < 40000; ++k) {
    // Ids first + 2k hold "tile k"; from k = 39,000 on, ids first + 2k + 1 hold "sea" as well.
    auto added = writer.value()->addTile(tileIdToZxy(first + 2 * k), "tile " + std::to_string(k));
    if (added && k >= 39000)
      added = writer.value()->addTile(tileIdToZxy(first + 2 * k + 1), "sea");
    if (!added) {
      std::fprintf(stderr, "%s\n", added.error().message.c_str());
      return 1;
    }
  }
  ArchiveMetadata m;
  m.name = "synthetic";
  m.tileFormat = "png";
  m.minZoom = m.maxZoom = m.centerZoom = 9;
  m.west = -180, m.south = -85, m.east = 180, m.north = 85;
  if (auto done = writer.value()->finish(m); !done) {
    std::fprintf(stderr, "%s\n", done.error().message.c_str());
    return 1;
  }
  return 0;
}
