#include "pmtiles_writer.h"

#include "hilbert_tile_id.h"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace strahler::archive {
namespace {

using base::ErrorCode;
using base::makeError;

base::Error ioError(const std::string& what, const std::string& path) {
  return {ErrorCode::kIoError, "cannot " + what + " '" + path + "': " + std::strerror(errno)};
}

std::int32_t e7(double degrees) {
  return static_cast<std::int32_t>(std::llround(degrees * 1e7));
}

pmtiles::TileType tileType(const std::string& format) {
  if (format == "png")
    return pmtiles::TileType::kPng;
  if (format == "pbf")
    return pmtiles::TileType::kMvt;
  if (format == "webp")
    return pmtiles::TileType::kWebp;
  if (format == "jpg" || format == "jpeg")
    return pmtiles::TileType::kJpeg;
  return pmtiles::TileType::kUnknown;
}

std::string metadataJson(const ArchiveMetadata& m) {
  nlohmann::ordered_json j = {{"name", m.name},         {"description", m.description},
                              {"version", m.version},   {"type", "baselayer"},
                              {"format", m.tileFormat}, {"tileSize", m.tileSize}};
  if (!m.attribution.empty())
    j["attribution"] = m.attribution;
  if (!m.encoding.empty())
    j["encoding"] = m.encoding;
  if (!m.vectorLayers.empty())
    j["vector_layers"] = nlohmann::ordered_json::parse(m.vectorLayers);
  for (const auto& [key, value] : m.extra)
    j[key] = value;
  return j.dump();
}

/// A spool file beside `path`, unlinked at once: only its descriptor keeps it.
std::FILE* openSpool(const std::string& path) {
  const std::string name = path + ".spool";
  const int fd = ::open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0)
    return nullptr;
  ::unlink(name.c_str());
  std::FILE* f = ::fdopen(fd, "w+b");
  if (f == nullptr)
    ::close(fd);
  return f;
}

} // namespace

base::Result<std::unique_ptr<PmtilesWriter>> PmtilesWriter::create(const std::string& path,
                                                                   pmtiles::Compression internal) {
  std::FILE* out = std::fopen(path.c_str(), "wb");
  if (out == nullptr)
    return ioError("create", path);
  std::FILE* spool = openSpool(path);
  if (spool == nullptr) {
    const base::Error e = ioError("create a spool file beside", path);
    std::fclose(out);
    return e;
  }
  return std::unique_ptr<PmtilesWriter>(new PmtilesWriter(path, out, spool, internal));
}

PmtilesWriter::PmtilesWriter(std::string path, std::FILE* out, std::FILE* spool,
                             pmtiles::Compression internal)
    : path_(std::move(path)), out_(out), spool_(spool), internal_(internal) {}

PmtilesWriter::~PmtilesWriter() {
  if (spool_ != nullptr)
    std::fclose(spool_);
  if (out_ != nullptr)
    std::fclose(out_);
}

base::Status PmtilesWriter::writeAll(std::FILE* file, std::string_view bytes) const {
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size())
    return ioError("write", path_);
  return base::Ok{};
}

base::Status PmtilesWriter::addTile(TileCoord tile, std::string_view bytes) {
  if (finished_)
    return makeError(ErrorCode::kInternal, "pmtiles: tile added after finish");
  const std::uint64_t id = zxyToTileId(tile);
  if (!entries_.empty()) {
    const pmtiles::Entry& last = entries_.back();
    if (id < last.tileId + last.runLength)
      return makeError(ErrorCode::kInternal, "pmtiles: tiles must come in ascending id order");
  }
  if (bytes.size() > UINT32_MAX)
    return makeError(ErrorCode::kLimitExceeded, "pmtiles: a tile larger than 4 GiB");
  const auto length = static_cast<std::uint32_t>(bytes.size());
  auto [it, fresh] = stored_.try_emplace(hashContent(bytes), Stored{stats_.tileBytes, length});
  if (fresh) {
    STRAHLER_RETURN_IF_ERROR(writeAll(spool_, bytes));
    stats_.tileBytes += length;
    ++stats_.uniqueTiles;
  }
  const Stored& s = it->second;
  ++stats_.tiles;
  minZoom_ = std::min(minZoom_, tile.z);
  maxZoom_ = std::max(maxZoom_, tile.z);
  if (!entries_.empty()) {
    pmtiles::Entry& last = entries_.back();
    if (last.tileId + last.runLength == id && last.offset == s.offset && last.length == s.length &&
        last.runLength < UINT32_MAX) {
      ++last.runLength;
      return base::Ok{};
    }
  }
  entries_.push_back({id, s.offset, s.length, 1});
  return base::Ok{};
}

base::Status PmtilesWriter::finish(const ArchiveMetadata& m) {
  if (finished_)
    return makeError(ErrorCode::kInternal, "pmtiles: finish called twice");
  finished_ = true;
  STRAHLER_ASSIGN_OR_RETURN(const pmtiles::Directories dirs,
                            pmtiles::buildDirectories(entries_, internal_));
  STRAHLER_ASSIGN_OR_RETURN(const std::string meta, pmtiles::compress(metadataJson(m), internal_));
  pmtiles::Header h;
  h.rootOffset = pmtiles::kHeaderBytes;
  h.rootLength = dirs.root.size();
  h.metadataOffset = h.rootOffset + h.rootLength;
  h.metadataLength = meta.size();
  h.leafOffset = h.metadataOffset + h.metadataLength;
  h.leafLength = dirs.leaves.size();
  h.tileDataOffset = h.leafOffset + h.leafLength;
  h.tileDataLength = stats_.tileBytes;
  h.addressedTiles = stats_.tiles;
  h.tileEntries = entries_.size();
  h.tileContents = stats_.uniqueTiles;
  h.clustered = true; // contents are spooled in tile id order; repeats point backwards
  h.internalCompression = internal_;
  // PNG is compressed already; vector tiles come gzipped.
  h.tileCompression = m.gzippedTiles ? pmtiles::Compression::kGzip : pmtiles::Compression::kNone;
  h.tileType = tileType(m.tileFormat);
  h.minZoom = static_cast<std::uint8_t>(entries_.empty() ? m.minZoom : minZoom_);
  h.maxZoom = static_cast<std::uint8_t>(entries_.empty() ? m.maxZoom : maxZoom_);
  h.minLonE7 = e7(m.west);
  h.minLatE7 = e7(m.south);
  h.maxLonE7 = e7(m.east);
  h.maxLatE7 = e7(m.north);
  h.centerZoom = static_cast<std::uint8_t>(m.centerZoom);
  h.centerLonE7 = e7(m.centerLon);
  h.centerLatE7 = e7(m.centerLat);
  for (const std::string& part : {pmtiles::encodeHeader(h), dirs.root, meta, dirs.leaves})
    STRAHLER_RETURN_IF_ERROR(writeAll(out_, part));
  if (std::fflush(spool_) != 0 || std::fseek(spool_, 0, SEEK_SET) != 0)
    return ioError("read back the spool of", path_);
  std::string buffer(1 << 20, '\0');
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), spool_)) > 0;)
    STRAHLER_RETURN_IF_ERROR(writeAll(out_, std::string_view(buffer).substr(0, n)));
  if (std::ferror(spool_))
    return ioError("read back the spool of", path_);
  std::fclose(spool_);
  spool_ = nullptr;
  const int flushed = std::fflush(out_);
  const int synced = flushed == 0 ? ::fsync(::fileno(out_)) : -1;
  const int closed = std::fclose(out_);
  out_ = nullptr;
  if (flushed != 0 || synced != 0 || closed != 0)
    return ioError("write", path_);
  return base::Ok{};
}

} // namespace strahler::archive
