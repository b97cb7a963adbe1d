// gzip::compress and gzip::decompress; zlib's own inflate reads what compress writes.
#include "gzip.h"
#include "result_matchers.h"

#include <gtest/gtest.h>

#include <string>
#include <zlib.h>

namespace strahler::gzip {
namespace {

/// `bytes` inflated by zlib directly as a gzip stream; "" if they are not one.
std::string zlibInflate(const std::string& bytes) {
  z_stream stream{};
  if (inflateInit2(&stream, 15 + 16) != Z_OK)
    return {};
  std::string out;
  char buffer[4096];
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  int result = Z_OK;
  while (result == Z_OK) {
    stream.next_out = reinterpret_cast<Bytef*>(buffer);
    stream.avail_out = sizeof buffer;
    result = inflate(&stream, Z_NO_FLUSH);
    out.append(buffer, sizeof buffer - stream.avail_out);
  }
  inflateEnd(&stream);
  return result == Z_STREAM_END ? out : std::string{};
}

std::string geojsonLikeText() {
  std::string text;
  for (int i = 0; i < 20000; ++i)
    text += "{\"coordinates\":[" + std::to_string(i * 0.001) + "," + std::to_string(i) + "]},";
  return text;
}

TEST(Gzip, CompressWritesAGzipMemberZlibInflatesBack) {
  const std::string text = geojsonLikeText();
  for (const Level level : {Level::kFastest, Level::kSmallest}) {
    const std::string packed = compress(text, level);
    EXPECT_LT(packed.size(), text.size() / 3);
    EXPECT_EQ(packed.substr(0, 2), std::string("\x1f\x8b", 2)) << "gzip magic";
    EXPECT_EQ(zlibInflate(packed), text);
    EXPECT_EQ(test_support::valueOf(decompress(packed, text.size())), text);
    EXPECT_EQ(compress(text, level), packed) << "the same bytes every time";
  }
  EXPECT_LE(compress(text, Level::kSmallest).size(), compress(text, Level::kFastest).size());
  EXPECT_FALSE(compress("", Level::kFastest).empty()) << "an empty text is still a gzip member";
  EXPECT_EQ(test_support::valueOf(decompress(compress("", Level::kFastest), 0)), "");
}

TEST(Gzip, DecompressRefusesDamagedTruncatedTrailingAndOversizedInput) {
  const std::string text = geojsonLikeText();
  const std::string packed = compress(text, Level::kSmallest);
  std::string damaged = packed;
  damaged[packed.size() / 2] = static_cast<char>(damaged[packed.size() / 2] ^ 0x55);
  const std::pair<std::string, std::string> bad[] = {
      {"not gzip at all", "gzip: damaged or truncated data"},
      {packed.substr(0, packed.size() / 2), "gzip: damaged or truncated data"},
      {packed.substr(0, packed.size() - 1), "gzip: damaged or truncated data"},
      {damaged, "gzip: damaged or truncated data"},
      {packed + "x", "gzip: bytes after the end of the gzip member"},
      {"", "gzip: damaged or truncated data"}};
  for (const auto& [input, message] : bad) {
    const auto out = decompress(input, text.size());
    ASSERT_FALSE(out.ok()) << input.size();
    EXPECT_EQ(out.error().code, base::ErrorCode::kCorrupt);
    EXPECT_EQ(out.error().message, message) << input.size();
  }
  // A bomb: 64 MB of zeros packs into ~64 KB; a small bound stops it early.
  const std::string bomb = compress(std::string(64u << 20, '\0'), Level::kSmallest);
  const auto big = decompress(bomb, 1u << 20);
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.error().code, base::ErrorCode::kInvalidInput);
  EXPECT_EQ(big.error().message, "gzip: the data inflate to more than 1048576 bytes");
  EXPECT_EQ(decompress(packed, text.size() - 1).error().code, base::ErrorCode::kInvalidInput);
}

} // namespace
} // namespace strahler::gzip
