#include "gzip.h"

#include "strahler/base/assert.h"

#include <limits>
#include <zlib.h>

namespace strahler::gzip {
namespace {

/// windowBits 15 + 16: zlib writes and reads a gzip header and trailer around the deflate data.
constexpr int kGzipWindowBits = 15 + 16;

} // namespace

std::string compress(std::string_view bytes, Level level) {
  STRAHLER_ASSERT(bytes.size() <= std::numeric_limits<uInt>::max(),
                  "more bytes than one zlib call takes");
  z_stream stream{};
  const int init =
      deflateInit2(&stream, level == Level::kFastest ? Z_BEST_SPEED : Z_BEST_COMPRESSION,
                   Z_DEFLATED, kGzipWindowBits, 8, Z_DEFAULT_STRATEGY);
  STRAHLER_ASSERT(init == Z_OK, "zlib could not start a gzip stream");
  std::string out(deflateBound(&stream, static_cast<uLong>(bytes.size())), '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  const int result = deflate(&stream, Z_FINISH);
  deflateEnd(&stream);
  STRAHLER_ASSERT(result == Z_STREAM_END, "zlib's bound did not hold the gzip stream");
  out.resize(stream.total_out);
  out.shrink_to_fit();
  return out;
}

base::Result<std::string> decompress(std::string_view packed, std::size_t maxBytes) {
  using base::ErrorCode;
  if (packed.size() > std::numeric_limits<uInt>::max())
    return base::makeError(ErrorCode::kInvalidInput, "gzip: more bytes than one zlib call takes");
  z_stream stream{};
  if (inflateInit2(&stream, kGzipWindowBits) != Z_OK)
    return base::makeError(ErrorCode::kInternal, "gzip: zlib could not start an inflate stream");
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data()));
  stream.avail_in = static_cast<uInt>(packed.size());
  std::string out;
  char buffer[65536];
  int result = Z_OK;
  while (result == Z_OK && out.size() <= maxBytes) {
    stream.next_out = reinterpret_cast<Bytef*>(buffer);
    stream.avail_out = sizeof buffer;
    result = inflate(&stream, Z_NO_FLUSH);
    out.append(buffer, sizeof buffer - stream.avail_out);
    if (result == Z_BUF_ERROR && stream.avail_in == 0)
      break; // the input ended before the member did
  }
  const uInt left = stream.avail_in;
  inflateEnd(&stream);
  if (out.size() > maxBytes)
    return base::makeError(ErrorCode::kInvalidInput, "gzip: the data inflate to more than " +
                                                         std::to_string(maxBytes) + " bytes");
  if (result != Z_STREAM_END)
    return base::makeError(ErrorCode::kCorrupt, "gzip: damaged or truncated data");
  if (left != 0)
    return base::makeError(ErrorCode::kCorrupt, "gzip: bytes after the end of the gzip member");
  return out;
}

} // namespace strahler::gzip
