#include "mbtiles_writer.h"

#include "strahler/geometry/tile_id.h"

#include <cstdio>
#include <sqlite3.h>

namespace strahler::archive {
namespace {

using base::ErrorCode;
using base::makeError;

constexpr const char* kSchema =
    "PRAGMA application_id = 0x4d504258;" // "MPBX", as MBTiles 1.3 suggests
    "PRAGMA journal_mode = OFF;"
    "PRAGMA synchronous = OFF;"
    "CREATE TABLE metadata (name TEXT, value TEXT);"
    "CREATE TABLE map (zoom_level INTEGER, tile_column INTEGER, tile_row INTEGER, tile_id TEXT);"
    "CREATE TABLE images (tile_data BLOB, tile_id TEXT);"
    "CREATE VIEW tiles AS SELECT map.zoom_level AS zoom_level, map.tile_column AS tile_column,"
    " map.tile_row AS tile_row, images.tile_data AS tile_data"
    " FROM map JOIN images ON images.tile_id = map.tile_id;"
    "BEGIN;";

constexpr const char* kIndexes =
    "CREATE UNIQUE INDEX map_index ON map (zoom_level, tile_column, tile_row);"
    "CREATE UNIQUE INDEX images_id ON images (tile_id);"
    "CREATE UNIQUE INDEX name ON metadata (name);";

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.7f", v);
  return text;
}

} // namespace

base::Result<std::unique_ptr<MbtilesWriter>> MbtilesWriter::create(const std::string& path) {
  sqlite3* db = nullptr;
  const int opened =
      sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  if (opened != SQLITE_OK) {
    const std::string message = db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(opened);
    sqlite3_close(db);
    return makeError(ErrorCode::kIoError, "cannot create '" + path + "': " + message);
  }
  std::unique_ptr<MbtilesWriter> writer(new MbtilesWriter(path, db));
  STRAHLER_RETURN_IF_ERROR(writer->execute(kSchema));
  if (sqlite3_prepare_v2(db, "INSERT INTO map VALUES (?, ?, ?, ?)", -1, &writer->insertMap_,
                         nullptr) != SQLITE_OK ||
      sqlite3_prepare_v2(db, "INSERT INTO images VALUES (?, ?)", -1, &writer->insertImage_,
                         nullptr) != SQLITE_OK)
    return writer->sqliteError("prepare the inserts of");
  return writer;
}

MbtilesWriter::MbtilesWriter(std::string path, sqlite3* db) : path_(std::move(path)), db_(db) {}

MbtilesWriter::~MbtilesWriter() {
  sqlite3_finalize(insertMap_);
  sqlite3_finalize(insertImage_);
  sqlite3_close(db_);
}

base::Error MbtilesWriter::sqliteError(const std::string& what) const {
  return {ErrorCode::kIoError, "cannot " + what + " '" + path_ + "': " + sqlite3_errmsg(db_)};
}

base::Status MbtilesWriter::execute(const char* sql) {
  char* message = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
    const std::string text = message != nullptr ? message : "unknown error";
    sqlite3_free(message);
    return makeError(ErrorCode::kIoError, "cannot write '" + path_ + "': " + text);
  }
  return base::Ok{};
}

base::Status MbtilesWriter::addTile(TileCoord tile, std::string_view bytes) {
  if (finished_)
    return makeError(ErrorCode::kInternal, "mbtiles: tile added after finish");
  const ContentHash hash = hashContent(bytes);
  const std::string id = hash.toHex();
  if (stored_.insert(hash).second) {
    sqlite3_reset(insertImage_);
    sqlite3_bind_blob64(insertImage_, 1, bytes.data(), bytes.size(), SQLITE_STATIC);
    sqlite3_bind_text(insertImage_, 2, id.c_str(), -1, SQLITE_STATIC);
    if (sqlite3_step(insertImage_) != SQLITE_DONE)
      return sqliteError("write a tile to");
    ++stats_.uniqueTiles;
    stats_.tileBytes += bytes.size();
  }
  const std::int64_t tmsRow = geometry::flipRow(tile.z, tile.y);
  sqlite3_reset(insertMap_);
  sqlite3_bind_int(insertMap_, 1, tile.z);
  sqlite3_bind_int64(insertMap_, 2, tile.x);
  sqlite3_bind_int64(insertMap_, 3, tmsRow);
  sqlite3_bind_text(insertMap_, 4, id.c_str(), -1, SQLITE_STATIC);
  if (sqlite3_step(insertMap_) != SQLITE_DONE)
    return sqliteError("write a tile to");
  ++stats_.tiles;
  return base::Ok{};
}

base::Status MbtilesWriter::finish(const ArchiveMetadata& m) {
  if (finished_)
    return makeError(ErrorCode::kInternal, "mbtiles: finish called twice");
  finished_ = true;
  STRAHLER_RETURN_IF_ERROR(execute(kIndexes));
  std::vector<std::pair<std::string, std::string>> rows = {
      {"name", m.name},
      {"format", m.tileFormat},
      {"bounds",
       number(m.west) + "," + number(m.south) + "," + number(m.east) + "," + number(m.north)},
      {"center",
       number(m.centerLon) + "," + number(m.centerLat) + "," + std::to_string(m.centerZoom)},
      {"minzoom", std::to_string(m.minZoom)},
      {"maxzoom", std::to_string(m.maxZoom)},
      {"type", "baselayer"},
      {"description", m.description},
      {"version", m.version},
      {"tileSize", std::to_string(m.tileSize)}};
  if (!m.attribution.empty())
    rows.emplace_back("attribution", m.attribution);
  if (!m.encoding.empty())
    rows.emplace_back("encoding", m.encoding);
  if (!m.vectorLayers.empty()) // MBTiles 1.3: a pbf tileset lists its layers in "json"
    rows.emplace_back("json", "{\"vector_layers\":" + m.vectorLayers + "}");
  rows.insert(rows.end(), m.extra.begin(), m.extra.end());
  sqlite3_stmt* insert = nullptr;
  if (sqlite3_prepare_v2(db_, "INSERT INTO metadata VALUES (?, ?)", -1, &insert, nullptr) !=
      SQLITE_OK)
    return sqliteError("write the metadata of");
  for (const auto& [name, value] : rows) {
    sqlite3_reset(insert);
    sqlite3_bind_text(insert, 1, name.c_str(), -1, SQLITE_STATIC);
    sqlite3_bind_text(insert, 2, value.c_str(), -1, SQLITE_STATIC);
    if (sqlite3_step(insert) != SQLITE_DONE) {
      sqlite3_finalize(insert);
      return sqliteError("write the metadata of");
    }
  }
  sqlite3_finalize(insert);
  STRAHLER_RETURN_IF_ERROR(execute("COMMIT;"));
  sqlite3_finalize(insertMap_);
  sqlite3_finalize(insertImage_);
  insertMap_ = insertImage_ = nullptr;
  const int closed = sqlite3_close(db_);
  db_ = nullptr;
  if (closed != SQLITE_OK)
    return makeError(ErrorCode::kIoError, "cannot close '" + path_ + "'");
  return base::Ok{};
}

} // namespace strahler::archive
