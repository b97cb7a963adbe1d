#include "strahler/store/world_file.h"

#include "file_io.h"
#include "world_proto.h"

#include <filesystem>
#include <limits>
#include <zlib.h>

namespace strahler::store {
namespace detail {
namespace {

constexpr std::string_view kMagic{"STRAHLERWORLD\0", 14};
static_assert(kWorldHeaderBytes == kMagic.size() + 4 + 8);

void appendLittleEndian(std::string& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i)
    out.push_back(static_cast<char>((value >> (8 * i)) & 0xFFu));
}

std::uint64_t readLittleEndian(std::string_view bytes, std::size_t offset, int count) {
  std::uint64_t value = 0;
  for (int i = count - 1; i >= 0; --i)
    value = (value << 8) | static_cast<unsigned char>(bytes[offset + static_cast<std::size_t>(i)]);
  return value;
}

std::uint32_t crc32Of(std::string_view bytes) {
  const auto* data = reinterpret_cast<const Bytef*>(bytes.data());
  return static_cast<std::uint32_t>(crc32_z(crc32_z(0, nullptr, 0), data, bytes.size()));
}

std::string hex32(std::uint32_t value) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out = "0x";
  for (int shift = 28; shift >= 0; shift -= 4)
    out.push_back(kDigits[(value >> shift) & 0xFu]);
  return out;
}

} // namespace

base::Error corruptError(std::string_view name, std::string_view what) {
  return base::makeError(base::ErrorCode::kCorrupt,
                         "world file '" + std::string(name) + "': " + std::string(what));
}

std::string frame(std::string_view payload, std::uint32_t version) {
  std::string out;
  out.reserve(kWorldHeaderBytes + payload.size() + kWorldTrailerBytes);
  out.append(kMagic);
  appendLittleEndian(out, version, 4);
  appendLittleEndian(out, payload.size(), 8);
  out.append(payload);
  appendLittleEndian(out, crc32Of(out), 4);
  return out;
}

base::Result<std::string_view> unframe(std::string_view bytes, std::string_view name) {
  const std::size_t overhead = kWorldHeaderBytes + kWorldTrailerBytes;
  if (bytes.size() > kMaxWorldFileBytes)
    return corruptError(name, std::to_string(bytes.size()) + " bytes, more than the limit of " +
                                  std::to_string(kMaxWorldFileBytes));
  if (bytes.size() < overhead)
    return corruptError(name, "truncated: " + std::to_string(bytes.size()) +
                                  " bytes, a world file has at least " + std::to_string(overhead));
  if (bytes.substr(0, kMagic.size()) != kMagic)
    return corruptError(name, "not a strahler world file (wrong magic bytes)");
  const auto version = static_cast<std::uint32_t>(readLittleEndian(bytes, kMagic.size(), 4));
  if (version != kWorldFormatVersion && version != kWorldFormatVersionWithoutRelief)
    return base::makeError(base::ErrorCode::kCorrupt,
                           "world file '" + std::string(name) + "' has format version " +
                               std::to_string(version) + ", this strahler reads versions " +
                               std::to_string(kWorldFormatVersionWithoutRelief) + " and " +
                               std::to_string(kWorldFormatVersion) +
                               ": generate it again with 'strahler generate'");
  const std::uint64_t length = readLittleEndian(bytes, kMagic.size() + 4, 8);
  if (length != bytes.size() - overhead)
    return corruptError(name, "the header announces a payload of " + std::to_string(length) +
                                  " bytes but the file holds " +
                                  std::to_string(bytes.size() - overhead) +
                                  " (truncated or extended)");
  const std::size_t checked = bytes.size() - kWorldTrailerBytes;
  const auto stored = static_cast<std::uint32_t>(readLittleEndian(bytes, checked, 4));
  const std::uint32_t computed = crc32Of(bytes.substr(0, checked));
  if (stored != computed)
    return corruptError(name, "checksum mismatch (stored " + hex32(stored) + ", computed " +
                                  hex32(computed) + ")");
  return bytes.substr(kWorldHeaderBytes, static_cast<std::size_t>(length));
}

} // namespace detail

std::string encodeWorld(const construction::WorldData& world) {
  const v1::World message = detail::toProto(world);
  std::string payload;
  const bool serialized = message.SerializeToString(&payload);
  STRAHLER_ASSERT(serialized, "protobuf could not serialise a world (larger than 2 GiB?)");
  return detail::frame(payload, world.relief.empty() ? kWorldFormatVersionWithoutRelief
                                                     : kWorldFormatVersion);
}

base::Result<construction::WorldData> decodeWorld(std::string_view bytes,
                                                  std::string_view nameForErrors) {
  STRAHLER_ASSIGN_OR_RETURN(const std::string_view payload, detail::unframe(bytes, nameForErrors));
  static_assert(kMaxWorldFileBytes <= std::numeric_limits<int>::max());
  v1::World message;
  if (!message.ParseFromArray(payload.data(), static_cast<int>(payload.size())))
    return detail::corruptError(nameForErrors, "the payload is not a valid strahler.v1.World "
                                               "protobuf message");
  return detail::fromProto(message, nameForErrors);
}

base::Status writeWorldFile(const std::string& path, const construction::WorldData& world) {
  removeStaleWorldTemporaries(std::filesystem::path(path).parent_path().string());
  return detail::writeFileAtomically(path, encodeWorld(world));
}

std::size_t removeStaleWorldTemporaries(const std::string& dir) {
  return detail::removeStaleTempFiles(dir, ".world", kStaleTemporaryAge);
}

base::Result<construction::WorldData> readWorldFile(const std::string& path) {
  auto bytes = detail::readWholeFile(path, kMaxWorldFileBytes);
  if (!bytes.ok()) {
    base::Error error = std::move(bytes).error();
    if (error.code == base::ErrorCode::kCorrupt)
      error.message = "world file " + error.message; // "world file 'path' is N bytes, more ..."
    return error;
  }
  return decodeWorld(bytes.value(), path);
}

} // namespace strahler::store
