#include "pmtiles_format.h"

#include "gzip.h"

#include <algorithm>
#include <cstring>

namespace strahler::archive::pmtiles {
namespace {

using base::ErrorCode;
using base::makeError;

/// The most a directory or the metadata may inflate to: far above any real archive's (a leaf
/// directory of 16,384 entries is ~100 KB), far below what would exhaust memory.
constexpr std::size_t kMaxInflatedBytes = 256u << 20;

void putVarint(std::string& out, std::uint64_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<char>((v & 0x7f) | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<char>(v));
}

/// Reads a varint at `pos`; false when truncated or longer than 64 bits.
bool getVarint(std::string_view in, std::size_t& pos, std::uint64_t& v) {
  v = 0;
  for (int shift = 0; shift < 64; shift += 7) {
    if (pos >= in.size())
      return false;
    const auto byte = static_cast<std::uint8_t>(in[pos++]);
    v |= static_cast<std::uint64_t>(byte & 0x7f) << shift;
    if ((byte & 0x80) == 0)
      return true;
  }
  return false;
}

template <class T> void putLe(std::string& out, T v) {
  for (std::size_t i = 0; i < sizeof(T); ++i)
    out.push_back(static_cast<char>((static_cast<std::uint64_t>(v) >> (8 * i)) & 0xff));
}

template <class T> T getLe(std::string_view in, std::size_t pos) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i)
    v |= static_cast<std::uint64_t>(static_cast<std::uint8_t>(in[pos + i])) << (8 * i);
  return static_cast<T>(v);
}

/// Root and leaves for leaves of `leafSize` entries.
base::Result<Directories> splitIntoLeaves(const std::vector<Entry>& entries, std::size_t leafSize,
                                          Compression compression) {
  Directories out;
  std::vector<Entry> rootEntries;
  for (std::size_t i = 0; i < entries.size(); i += leafSize) {
    const std::vector<Entry> chunk(
        entries.begin() + static_cast<std::ptrdiff_t>(i),
        entries.begin() + static_cast<std::ptrdiff_t>(std::min(i + leafSize, entries.size())));
    STRAHLER_ASSIGN_OR_RETURN(const std::string leaf,
                              compress(encodeDirectory(chunk), compression));
    rootEntries.push_back(
        {chunk.front().tileId, out.leaves.size(), static_cast<std::uint32_t>(leaf.size()), 0});
    out.leaves += leaf;
    ++out.leafCount;
  }
  STRAHLER_ASSIGN_OR_RETURN(out.root, compress(encodeDirectory(rootEntries), compression));
  return out;
}

} // namespace

std::string encodeHeader(const Header& h) {
  std::string out("PMTiles\x03", 8);
  for (const std::uint64_t v :
       {h.rootOffset, h.rootLength, h.metadataOffset, h.metadataLength, h.leafOffset, h.leafLength,
        h.tileDataOffset, h.tileDataLength, h.addressedTiles, h.tileEntries, h.tileContents})
    putLe(out, v);
  putLe(out, static_cast<std::uint8_t>(h.clustered ? 1 : 0));
  putLe(out, static_cast<std::uint8_t>(h.internalCompression));
  putLe(out, static_cast<std::uint8_t>(h.tileCompression));
  putLe(out, static_cast<std::uint8_t>(h.tileType));
  putLe(out, h.minZoom);
  putLe(out, h.maxZoom);
  for (const std::int32_t v : {h.minLonE7, h.minLatE7, h.maxLonE7, h.maxLatE7})
    putLe(out, static_cast<std::uint32_t>(v));
  putLe(out, h.centerZoom);
  putLe(out, static_cast<std::uint32_t>(h.centerLonE7));
  putLe(out, static_cast<std::uint32_t>(h.centerLatE7));
  return out;
}

base::Result<Header> decodeHeader(std::string_view in) {
  if (in.size() < kHeaderBytes || in.substr(0, 7) != "PMTiles")
    return makeError(ErrorCode::kCorrupt, "pmtiles: not a PMTiles archive");
  if (in[7] != 3)
    return makeError(ErrorCode::kCorrupt, "pmtiles: version " +
                                              std::to_string(static_cast<int>(in[7])) +
                                              " (only version 3 is read)");
  Header h;
  std::uint64_t* fields[] = {&h.rootOffset,     &h.rootLength,     &h.metadataOffset,
                             &h.metadataLength, &h.leafOffset,     &h.leafLength,
                             &h.tileDataOffset, &h.tileDataLength, &h.addressedTiles,
                             &h.tileEntries,    &h.tileContents};
  std::size_t pos = 8;
  for (std::uint64_t* f : fields) {
    *f = getLe<std::uint64_t>(in, pos);
    pos += 8;
  }
  h.clustered = in[96] != 0;
  h.internalCompression = static_cast<Compression>(in[97]);
  h.tileCompression = static_cast<Compression>(in[98]);
  h.tileType = static_cast<TileType>(in[99]);
  h.minZoom = getLe<std::uint8_t>(in, 100);
  h.maxZoom = getLe<std::uint8_t>(in, 101);
  h.minLonE7 = static_cast<std::int32_t>(getLe<std::uint32_t>(in, 102));
  h.minLatE7 = static_cast<std::int32_t>(getLe<std::uint32_t>(in, 106));
  h.maxLonE7 = static_cast<std::int32_t>(getLe<std::uint32_t>(in, 110));
  h.maxLatE7 = static_cast<std::int32_t>(getLe<std::uint32_t>(in, 114));
  h.centerZoom = getLe<std::uint8_t>(in, 118);
  h.centerLonE7 = static_cast<std::int32_t>(getLe<std::uint32_t>(in, 119));
  h.centerLatE7 = static_cast<std::int32_t>(getLe<std::uint32_t>(in, 123));
  return h;
}

std::string encodeDirectory(const std::vector<Entry>& entries) {
  std::string out;
  putVarint(out, entries.size());
  std::uint64_t last = 0;
  for (const Entry& e : entries) {
    putVarint(out, e.tileId - last);
    last = e.tileId;
  }
  for (const Entry& e : entries)
    putVarint(out, e.runLength);
  for (const Entry& e : entries)
    putVarint(out, e.length);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const bool contiguous =
        i > 0 && entries[i].offset == entries[i - 1].offset + entries[i - 1].length;
    putVarint(out, contiguous ? 0 : entries[i].offset + 1);
  }
  return out;
}

base::Result<std::vector<Entry>> decodeDirectory(std::string_view in) {
  const auto truncated = [] {
    return makeError(ErrorCode::kCorrupt, "pmtiles: truncated or damaged directory");
  };
  std::size_t pos = 0;
  std::uint64_t count = 0;
  if (!getVarint(in, pos, count) || count > in.size())
    return truncated();
  std::vector<Entry> entries(count);
  std::uint64_t v = 0, id = 0;
  for (Entry& e : entries) {
    if (!getVarint(in, pos, v))
      return truncated();
    e.tileId = id += v;
  }
  for (Entry& e : entries) {
    if (!getVarint(in, pos, v) || v > UINT32_MAX)
      return truncated();
    e.runLength = static_cast<std::uint32_t>(v);
  }
  for (Entry& e : entries) {
    if (!getVarint(in, pos, v) || v > UINT32_MAX)
      return truncated();
    e.length = static_cast<std::uint32_t>(v);
  }
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (!getVarint(in, pos, v) || (v == 0 && i == 0))
      return truncated();
    entries[i].offset = v == 0 ? entries[i - 1].offset + entries[i - 1].length : v - 1;
  }
  if (pos != in.size())
    return truncated();
  return entries;
}

base::Result<std::string> compress(std::string_view bytes, Compression compression) {
  if (compression == Compression::kNone)
    return std::string(bytes);
  if (compression == Compression::kGzip)
    return gzip::compress(bytes, gzip::Level::kSmallest);
  return makeError(ErrorCode::kUnsupported, "pmtiles: only none and gzip compression are written");
}

base::Result<std::string> decompress(std::string_view bytes, Compression compression) {
  if (compression == Compression::kNone)
    return std::string(bytes);
  if (compression == Compression::kGzip) {
    auto inflated = gzip::decompress(bytes, kMaxInflatedBytes);
    if (!inflated)
      return makeError(inflated.error().code, "pmtiles: " + inflated.error().message);
    return inflated;
  }
  return makeError(ErrorCode::kUnsupported, "pmtiles: only none and gzip compression are read");
}

base::Result<Directories> buildDirectories(const std::vector<Entry>& entries,
                                           Compression compression, std::size_t rootLimit) {
  if (entries.size() < 16384) {
    STRAHLER_ASSIGN_OR_RETURN(std::string root, compress(encodeDirectory(entries), compression));
    if (root.size() <= rootLimit)
      return Directories{std::move(root), {}, 0};
  }
  double leafSize = std::max(4096.0, static_cast<double>(entries.size()) / 3500.0);
  // Few entries with a tiny root limit (tests): start small enough to split at all.
  leafSize = std::min(leafSize, std::max(1.0, static_cast<double>(entries.size()) / 2.0));
  for (;;) {
    STRAHLER_ASSIGN_OR_RETURN(
        Directories d, splitIntoLeaves(entries, static_cast<std::size_t>(leafSize), compression));
    if (d.root.size() <= rootLimit)
      return d;
    if (leafSize >= static_cast<double>(entries.size()))
      return makeError(ErrorCode::kLimitExceeded, "pmtiles: the root directory does not fit in " +
                                                      std::to_string(rootLimit) + " bytes");
    leafSize *= 1.2;
  }
}

} // namespace strahler::archive::pmtiles
