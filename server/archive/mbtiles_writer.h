#pragma once

#include "content_hash.h"
#include "tile_archive.h"

#include <memory>
#include <string>
#include <unordered_set>

struct sqlite3;
struct sqlite3_stmt;

namespace strahler::archive {

/// Writes an MBTiles 1.3 file with the deduplicating schema that tileserver-gl and martin
/// read: `images(tile_data, tile_id)` holds each distinct content once (tile_id: its 128-bit
/// hash in hex), `map(zoom_level, tile_column, tile_row, tile_id)` every tile, and the view
/// `tiles` joins them. Rows are TMS (tile_row = 2^z − 1 − y). One transaction, no journal:
/// the file is a temporary until the caller renames it.
class MbtilesWriter final : public TileArchiveSink {
public:
  /// Creates the database at `path` (which must not exist); kIoError if SQLite cannot.
  static base::Result<std::unique_ptr<MbtilesWriter>> create(const std::string& path);
  ~MbtilesWriter() override;
  MbtilesWriter(const MbtilesWriter&) = delete;
  MbtilesWriter& operator=(const MbtilesWriter&) = delete;

  base::Status addTile(TileCoord tile, std::string_view bytes) override;
  base::Status finish(const ArchiveMetadata& metadata) override;
  ArchiveStats stats() const override { return stats_; }

private:
  MbtilesWriter(std::string path, sqlite3* db);
  base::Status execute(const char* sql);
  base::Error sqliteError(const std::string& what) const;

  std::string path_;
  sqlite3* db_ = nullptr;
  sqlite3_stmt* insertMap_ = nullptr;
  sqlite3_stmt* insertImage_ = nullptr;
  std::unordered_set<ContentHash, ContentHashHasher> stored_; ///< Contents in `images`.
  ArchiveStats stats_;
  bool finished_ = false;
};

} // namespace strahler::archive
