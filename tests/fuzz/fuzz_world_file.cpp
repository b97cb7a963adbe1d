// libFuzzer harness: world file bytes through decodeWorld. The first input byte picks the form
// of the rest: even, a whole file as read from disk (the header and checksum are fuzzed too);
// odd, a payload that the harness frames with a valid header and CRC-32, so that mutations
// reach the payload's validation instead of stopping at the checksum. A world that decodes
// must be one encodeWorld accepts (it asserts the invariants decodeWorld promises to check)
// and must read back to the same bytes.
#include "fuzz_support.h"

#include "strahler/store/world_file.h"

#include <string>
#include <zlib.h>

namespace {

void appendLittleEndian(std::string& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i)
    out += static_cast<char>((value >> (8 * i)) & 0xff);
}

/// `payload` framed as a current world file: magic, version, length, payload, CRC-32.
std::string frame(std::string_view payload) {
  std::string file("STRAHLERWORLD\0", 14);
  appendLittleEndian(file, strahler::store::kWorldFormatVersion, 4);
  appendLittleEndian(file, payload.size(), 8);
  file.append(payload);
  const auto crc =
      crc32(0L, reinterpret_cast<const Bytef*>(file.data()), static_cast<uInt>(file.size()));
  appendLittleEndian(file, crc, 4);
  return file;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace strahler;
  if (size == 0)
    return 0;
  const std::string_view rest = fuzz::asText(data + 1, size - 1);
  const std::string file = (data[0] & 1) ? frame(rest) : std::string(rest);
  const auto world = store::decodeWorld(file, "fuzz.world");
  fuzz::requireNoInternalError(world);
  if (!world)
    return 0;
  const std::string encoded = store::encodeWorld(world.value());
  const auto again = store::decodeWorld(encoded, "re-encoded.world");
  fuzz::require(again.ok(), "a decoded world encodes to a file that decodes");
  fuzz::require(store::encodeWorld(again.value()) == encoded, "encoding is stable");
  return 0;
}
