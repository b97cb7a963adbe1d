#pragma once

#include "content_hash.h"
#include "pmtiles_format.h"
#include "tile_archive.h"

#include <cstdio>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace strahler::archive {

/// Writes a PMTiles v3 archive: identical tile contents are stored once (by 128-bit hash) and
/// consecutive tile ids with one content share a run-length entry; the tile data is clustered
/// (in tile id order). Tile bytes go to an unlinked spool file until finish() lays out the
/// archive: header, root directory, metadata, leaf directories, tile data.
class PmtilesWriter final : public TileArchiveSink {
public:
  /// Creates the archive file at `path` (replacing any file there); kIoError if it cannot.
  static base::Result<std::unique_ptr<PmtilesWriter>>
  create(const std::string& path, pmtiles::Compression internal = pmtiles::Compression::kGzip);
  ~PmtilesWriter() override;
  PmtilesWriter(const PmtilesWriter&) = delete;
  PmtilesWriter& operator=(const PmtilesWriter&) = delete;

  base::Status addTile(TileCoord tile, std::string_view bytes) override;
  base::Status finish(const ArchiveMetadata& metadata) override;
  ArchiveStats stats() const override { return stats_; }

private:
  PmtilesWriter(std::string path, std::FILE* out, std::FILE* spool, pmtiles::Compression internal);
  base::Status writeAll(std::FILE* file, std::string_view bytes) const;

  std::string path_;
  std::FILE* out_ = nullptr;
  std::FILE* spool_ = nullptr; ///< Unlinked: vanishes with the process, whatever kills it.
  pmtiles::Compression internal_;
  std::vector<pmtiles::Entry> entries_;
  struct Stored {
    std::uint64_t offset;
    std::uint32_t length;
  };
  std::unordered_map<ContentHash, Stored, ContentHashHasher> stored_;
  ArchiveStats stats_;
  int minZoom_ = 255, maxZoom_ = -1;
  bool finished_ = false;
};

} // namespace strahler::archive
