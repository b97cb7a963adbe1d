#pragma once
// The PMTiles v3 binary format (https://github.com/protomaps/PMTiles/blob/main/spec/v3/spec.md):
// the 127-byte header, varint directories, root/leaf splitting and internal gzip. No file I/O.

#include "strahler/base/result.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace strahler::archive::pmtiles {

/// Size of the fixed header, bytes.
inline constexpr std::size_t kHeaderBytes = 127;
/// The header and the root directory must fit in the first 16 KiB of an archive.
inline constexpr std::size_t kRootLimitBytes = 16384 - kHeaderBytes;

/// Compression codes of the header.
enum class Compression : std::uint8_t {
  kUnknown = 0,
  kNone = 1,
  kGzip = 2,
  kBrotli = 3,
  kZstd = 4
};
/// Tile type codes of the header.
enum class TileType : std::uint8_t { kUnknown = 0, kMvt = 1, kPng = 2, kJpeg = 3, kWebp = 4 };

/// One directory entry: a run of `runLength` consecutive tile ids sharing one content, or
/// (runLength 0) a pointer to a leaf directory at `offset` in the leaf section.
struct Entry {
  std::uint64_t tileId = 0;
  std::uint64_t offset = 0; ///< From the start of the tile data (or leaf) section, bytes.
  std::uint32_t length = 0; ///< Bytes.
  std::uint32_t runLength = 1;

  friend bool operator==(const Entry&, const Entry&) = default;
};

/// The fixed header. Offsets and lengths in bytes, coordinates in degrees × 10⁷.
struct Header {
  std::uint64_t rootOffset = 0, rootLength = 0;
  std::uint64_t metadataOffset = 0, metadataLength = 0;
  std::uint64_t leafOffset = 0, leafLength = 0;
  std::uint64_t tileDataOffset = 0, tileDataLength = 0;
  std::uint64_t addressedTiles = 0, tileEntries = 0, tileContents = 0;
  bool clustered = false;
  Compression internalCompression = Compression::kGzip;
  Compression tileCompression = Compression::kNone;
  TileType tileType = TileType::kPng;
  std::uint8_t minZoom = 0, maxZoom = 0;
  std::int32_t minLonE7 = 0, minLatE7 = 0, maxLonE7 = 0, maxLatE7 = 0;
  std::uint8_t centerZoom = 0;
  std::int32_t centerLonE7 = 0, centerLatE7 = 0;
};

/// The 127 bytes of `header` (magic "PMTiles", version 3, little-endian fields).
std::string encodeHeader(const Header& header);
/// Parses a header; kCorrupt if the magic, the version or the size is wrong.
base::Result<Header> decodeHeader(std::string_view bytes);

/// The uncompressed directory of `entries` (ascending tile ids): count, tile id deltas, run
/// lengths, lengths, offsets (0 when contiguous with the previous entry, else offset + 1).
std::string encodeDirectory(const std::vector<Entry>& entries);
/// Parses an uncompressed directory; kCorrupt on truncation or overflow.
base::Result<std::vector<Entry>> decodeDirectory(std::string_view bytes);

/// `bytes` compressed with `compression` (kNone or kGzip).
base::Result<std::string> compress(std::string_view bytes, Compression compression);
/// The inverse of compress.
base::Result<std::string> decompress(std::string_view bytes, Compression compression);

/// A root directory and the leaf directories it points to, both compressed.
struct Directories {
  std::string root;
  std::string leaves;
  std::size_t leafCount = 0;
};

/// Puts `entries` in a root directory of at most `rootLimit` compressed bytes, splitting them
/// into leaf directories when they do not fit (as go-pmtiles does: leaves of ≥ 4,096 entries,
/// 20 % larger each try).
base::Result<Directories> buildDirectories(const std::vector<Entry>& entries,
                                           Compression compression,
                                           std::size_t rootLimit = kRootLimitBytes);

} // namespace strahler::archive::pmtiles
