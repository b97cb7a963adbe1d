#include "content_encoding.h"

#include <gtest/gtest.h>

#include <string>
#include <zlib.h>

namespace strahler::app {
namespace {

/// `bytes` inflated by zlib as a gzip stream; "" if they are not one.
std::string gunzip(const std::string& bytes) {
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

TEST(ContentEncoding, AcceptsGzipAsBrowsersAndCurlAskForIt) {
  EXPECT_TRUE(acceptsGzip("gzip"));
  EXPECT_TRUE(acceptsGzip("gzip, deflate, br, zstd"));
  EXPECT_TRUE(acceptsGzip("deflate, GZIP;q=0.5"));
  EXPECT_TRUE(acceptsGzip("x-gzip"));
  EXPECT_TRUE(acceptsGzip("br;q=1.0, *;q=0.1"));
}

TEST(ContentEncoding, RefusedOrAbsentGzipIsNotAccepted) {
  EXPECT_FALSE(acceptsGzip(""));
  EXPECT_FALSE(acceptsGzip("identity"));
  EXPECT_FALSE(acceptsGzip("br, deflate"));
  EXPECT_FALSE(acceptsGzip("gzip;q=0"));
  EXPECT_FALSE(acceptsGzip("gzip; q=0.000"));
  EXPECT_FALSE(acceptsGzip("gzip;q=0, *"));
  EXPECT_FALSE(acceptsGzip("*;q=0"));
  EXPECT_FALSE(acceptsGzip("gzip;q=2")) << "a q above 1 is malformed";
  EXPECT_FALSE(acceptsGzip("gzip;q=abc"));
  EXPECT_FALSE(acceptsGzip("gzipped"));
}

TEST(ContentEncoding, GzippedTextInflatesBackToItself) {
  std::string text;
  for (int i = 0; i < 20000; ++i)
    text += "{\"coordinates\":[" + std::to_string(i * 0.001) + "," + std::to_string(i) + "]},";
  const std::string packed = gzipped(text);
  EXPECT_LT(packed.size(), text.size() / 3);
  EXPECT_EQ(packed.substr(0, 2), std::string("\x1f\x8b", 2)) << "gzip magic";
  EXPECT_EQ(gunzip(packed), text);
  EXPECT_EQ(gunzip(gzipped("")), "");
  EXPECT_FALSE(gzipped("").empty()) << "an empty text is still a gzip member";
}

} // namespace
} // namespace strahler::app
