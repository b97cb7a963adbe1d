#pragma once
// The common interface of the archive writers: tiles go in one by one, in ascending Hilbert
// tile id order, then the metadata, and the file is complete.

#include "strahler/base/result.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace strahler::archive {

/// A Web Mercator XYZ tile (y from the north, as in URLs).
struct TileCoord {
  int z = 0;
  std::uint32_t x = 0;
  std::uint32_t y = 0;

  friend bool operator==(const TileCoord&, const TileCoord&) = default;
};

/// What an archive says about its tiles. Angles in degrees (WGS84).
struct ArchiveMetadata {
  std::string name;
  std::string description;
  std::string attribution; ///< Empty: none.
  std::string version;     ///< Version of the tile set, e.g. "1.0.0".
  std::string tileFormat;  ///< "png", or "pbf" for Mapbox Vector Tiles.
  std::string encoding;    ///< raster-dem encoding ("mapbox", "terrarium"); empty if none.
  int tileSize = 256;      ///< Pixels per side.
  int minZoom = 0;
  int maxZoom = 0;
  double west = 0.0, south = 0.0, east = 0.0, north = 0.0;
  double centerLon = 0.0, centerLat = 0.0;
  int centerZoom = 0;
  /// Vector tiles only: the TileJSON vector_layers array as JSON text; "" for rasters.
  std::string vectorLayers;
  /// True when the tiles' bytes are gzipped (vector tiles, as MBTiles' pbf and PMTiles'
  /// tile_compression 2 have them).
  bool gzippedTiles = false;
  /// More string fields written as they are (generator, world id, seed, ...).
  std::vector<std::pair<std::string, std::string>> extra;
};

/// Figures of an archive being written.
struct ArchiveStats {
  std::uint64_t tiles = 0;       ///< Tiles added (addressed).
  std::uint64_t uniqueTiles = 0; ///< Distinct tile contents stored.
  std::uint64_t tileBytes = 0;   ///< Bytes of the distinct contents.
};

/// Receives the tiles of an archive. Not thread-safe: one writer thread.
class TileArchiveSink {
public:
  virtual ~TileArchiveSink() = default;
  /// Adds a tile; tiles must come in strictly ascending Hilbert tile id order.
  virtual base::Status addTile(TileCoord tile, std::string_view bytes) = 0;
  /// Writes the indexes and `metadata`, then closes the file. Call once, after the last tile.
  virtual base::Status finish(const ArchiveMetadata& metadata) = 0;
  /// The figures so far.
  virtual ArchiveStats stats() const = 0;
};

} // namespace strahler::archive
