#include "content_encoding.h"

#include <gtest/gtest.h>

#include <string>

namespace strahler::app {
namespace {

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

} // namespace
} // namespace strahler::app
