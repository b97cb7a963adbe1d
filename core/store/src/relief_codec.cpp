#include "relief_codec.h"

#include "world_proto.h"

#include "strahler/base/assert.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>
#include <zlib.h>

namespace strahler::store::detail {
namespace {

using construction::ReliefResidual;
constexpr int kChunk = ReliefResidual::kChunk;
constexpr std::size_t kChunkNodes = static_cast<std::size_t>(kChunk) * kChunk;
/// Most bytes a chunk's varints take: a prediction error of int16 values is below 2^18 in
/// zigzag form, 3 bytes.
constexpr std::size_t kMaxChunkBytes = kChunkNodes * 3;

std::uint32_t zigzag(std::int32_t v) {
  return (static_cast<std::uint32_t>(v) << 1) ^ static_cast<std::uint32_t>(v >> 31);
}

std::int32_t unzigzag(std::uint32_t u) {
  return static_cast<std::int32_t>(u >> 1) ^ -static_cast<std::int32_t>(u & 1u);
}

/// The planar prediction of value (c, r) of a chunk from its left, upper and upper-left
/// neighbours (0 outside the chunk).
template <class Get> std::int32_t predict(const Get& get, int c, int r) {
  const std::int32_t left = c > 0 ? get(c - 1, r) : 0;
  const std::int32_t up = r > 0 ? get(c, r - 1) : 0;
  const std::int32_t corner = c > 0 && r > 0 ? get(c - 1, r - 1) : 0;
  return left + up - corner;
}

base::Error corrupt(std::string_view name, const std::string& what) {
  return corruptError(name, "relief: " + what);
}

} // namespace

void encodeRelief(const ReliefResidual& relief, v1::Relief& out) {
  STRAHLER_ASSERT(relief.columns % kChunk == 0 && relief.rows % kChunk == 0 &&
                      relief.column0 % kChunk == 0 && relief.row0 % kChunk == 0,
                  "a relief residual is not aligned to its chunks");
  STRAHLER_ASSERT(relief.quanta.size() == static_cast<std::size_t>(relief.columns) *
                                              static_cast<std::size_t>(relief.rows),
                  "a relief residual's size does not match its columns and rows");
  out.set_spacing(relief.spacing);
  out.set_column0(relief.column0);
  out.set_row0(relief.row0);
  out.set_columns(static_cast<std::uint32_t>(relief.columns));
  out.set_rows(static_cast<std::uint32_t>(relief.rows));
  out.set_chunk_size(kChunk);
  std::string varints;
  std::vector<Bytef> packed;
  for (int cr = 0; cr < relief.rows / kChunk; ++cr)
    for (int cc = 0; cc < relief.columns / kChunk; ++cc) {
      const auto get = [&](int c, int r) -> std::int32_t {
        return relief.quanta[static_cast<std::size_t>(cr * kChunk + r) *
                                 static_cast<std::size_t>(relief.columns) +
                             static_cast<std::size_t>(cc * kChunk + c)];
      };
      varints.clear();
      bool zero = true;
      for (int r = 0; r < kChunk; ++r)
        for (int c = 0; c < kChunk; ++c) {
          zero = zero && get(c, r) == 0;
          std::uint32_t u = zigzag(get(c, r) - predict(get, c, r));
          while (u >= 0x80u) {
            varints.push_back(static_cast<char>((u & 0x7Fu) | 0x80u));
            u >>= 7;
          }
          varints.push_back(static_cast<char>(u));
        }
      std::string* chunk = out.add_chunks();
      if (zero)
        continue;
      uLongf size = compressBound(static_cast<uLong>(varints.size()));
      packed.resize(size);
      const int status =
          compress2(packed.data(), &size, reinterpret_cast<const Bytef*>(varints.data()),
                    static_cast<uLong>(varints.size()), 9);
      STRAHLER_ASSERT(status == Z_OK, "zlib could not deflate a relief chunk");
      chunk->assign(reinterpret_cast<const char*>(packed.data()), size);
    }
}

base::Result<ReliefResidual> decodeRelief(const v1::Relief& m, std::string_view name) {
  ReliefResidual relief;
  if (!(std::isfinite(m.spacing()) && m.spacing() >= 1.0 && m.spacing() <= 1000.0))
    return corrupt(name, "spacing " + std::to_string(m.spacing()) + " m is outside [1, 1000]");
  if (m.chunk_size() != static_cast<std::uint32_t>(kChunk))
    return corrupt(name, "chunk size " + std::to_string(m.chunk_size()) + ", expected " +
                             std::to_string(kChunk));
  if (m.column0() % kChunk != 0 || m.row0() % kChunk != 0 || m.columns() % kChunk != 0 ||
      m.rows() % kChunk != 0 || m.columns() == 0 || m.rows() == 0)
    return corrupt(name, "the lattice (" + std::to_string(m.column0()) + ", " +
                             std::to_string(m.row0()) + ") + " + std::to_string(m.columns()) +
                             " × " + std::to_string(m.rows()) +
                             " is not a non-empty whole number of chunks");
  const std::uint64_t nodes = std::uint64_t{m.columns()} * m.rows();
  if (nodes > kMaxReliefNodes)
    return corrupt(name, std::to_string(nodes) + " nodes, more than the limit of " +
                             std::to_string(kMaxReliefNodes));
  const std::uint64_t chunkColumns = m.columns() / kChunk, chunkRows = m.rows() / kChunk;
  if (static_cast<std::uint64_t>(m.chunks_size()) != chunkColumns * chunkRows)
    return corrupt(name, std::to_string(m.chunks_size()) + " chunks, expected " +
                             std::to_string(chunkColumns * chunkRows));
  if (std::abs(static_cast<double>(m.column0()) * m.spacing()) > 1e9 ||
      std::abs(static_cast<double>(m.row0()) * m.spacing()) > 1e9)
    return corrupt(name, "the lattice lies more than 10^9 m from the centre");
  relief.spacing = m.spacing();
  relief.column0 = m.column0();
  relief.row0 = m.row0();
  relief.columns = static_cast<std::int32_t>(m.columns());
  relief.rows = static_cast<std::int32_t>(m.rows());
  relief.quanta.assign(nodes, 0);
  std::vector<Bytef> varints(kMaxChunkBytes + 1);
  for (std::uint64_t k = 0; k < chunkColumns * chunkRows; ++k) {
    const std::string& bytes = m.chunks(static_cast<int>(k));
    if (bytes.empty())
      continue;
    const std::string where = "chunk " + std::to_string(k) + ": ";
    uLongf size = static_cast<uLongf>(varints.size());
    const int status =
        uncompress(varints.data(), &size, reinterpret_cast<const Bytef*>(bytes.data()),
                   static_cast<uLong>(bytes.size()));
    if (status != Z_OK || size > kMaxChunkBytes)
      return corrupt(name, where + "not a valid zlib stream of at most " +
                               std::to_string(kMaxChunkBytes) + " bytes");
    const std::size_t cc = k % chunkColumns, cr = k / chunkColumns;
    const auto at = [&](int c, int r) -> std::int16_t& {
      return relief.quanta[(cr * kChunk + static_cast<std::size_t>(r)) *
                               static_cast<std::size_t>(relief.columns) +
                           cc * kChunk + static_cast<std::size_t>(c)];
    };
    const auto get = [&](int c, int r) -> std::int32_t { return at(c, r); };
    std::size_t read = 0;
    for (int r = 0; r < kChunk; ++r)
      for (int c = 0; c < kChunk; ++c) {
        std::uint32_t u = 0;
        for (int shift = 0;; shift += 7) {
          if (read >= size || shift > 21)
            return corrupt(name, where + "a truncated or overlong varint");
          const auto byte = static_cast<std::uint32_t>(varints[read++]);
          u |= (byte & 0x7Fu) << shift;
          if ((byte & 0x80u) == 0)
            break;
        }
        const std::int64_t value = std::int64_t{predict(get, c, r)} + unzigzag(u);
        if (value < std::numeric_limits<std::int16_t>::min() ||
            value > std::numeric_limits<std::int16_t>::max())
          return corrupt(name, where + "a value outside the 16-bit range");
        at(c, r) = static_cast<std::int16_t>(value);
      }
    if (read != size)
      return corrupt(name, where + std::to_string(size - read) + " bytes after its values");
  }
  return relief;
}

} // namespace strahler::store::detail
