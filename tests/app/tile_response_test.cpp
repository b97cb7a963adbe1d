// The one mapping from a tile's outcome to HTTP, and the tile's ETag and 304.
#include "tile_response.h"

#include <gtest/gtest.h>

#include <string>

namespace strahler::app {
namespace {

using service::TileCache;
using service::TileStatus;

/// The value of header `name` in `r` (its own fields, not prepared ones), or "".
std::string header(const http::Response& r, const std::string& name) {
  for (const auto& [k, v] : r.headers)
    if (k == name)
      return v;
  return {};
}

TEST(TileResponse, EachOutcomeWithoutATileHasItsStatus) {
  const struct {
    TileStatus status;
    int http;
  } cases[] = {{TileStatus::kNotFound, 404},
               {TileStatus::kUnsupported, 501},
               {TileStatus::kRetryLater, 503},
               {TileStatus::kFailed, 500},
               {TileStatus::kOk, 500}}; // an ok without a tile is a failure
  for (const auto& c : cases) {
    const http::Response r = tileResponse({nullptr, c.status, "why \"not\""});
    EXPECT_EQ(r.status, c.http) << c.http;
    EXPECT_EQ(r.route, "tile");
    EXPECT_EQ(r.body, "{\"error\": \"why \\\"not\\\"\"}") << c.http;
    EXPECT_EQ(header(r, "Content-Type"), "application/json");
    EXPECT_EQ(header(r, "Retry-After"), c.http == 503 ? "1" : "") << c.http;
    EXPECT_FALSE(r.sharedBody);
  }
}

TEST(TileResponse, AnOkOutcomeSendsTheCachedBytesAndPreparedFields) {
  RenderedTile rendered;
  rendered.bytes = "PNG bytes";
  rendered.mimeType = "image/png";
  rendered.evaluateMs = 1.5;
  rendered.encodeMs = 0.25;
  const auto tile = cachedTile(rendered, "\"0123456789abcdef\"");
  EXPECT_EQ(tile->bytes, "PNG bytes");
  EXPECT_EQ(tile->etag, "\"0123456789abcdef\"");
  const std::string& fields = tile->httpFields;
  for (const char* field :
       {"Content-Type: image/png\r\n", "ETag: \"0123456789abcdef\"\r\n",
        "Cache-Control: public, max-age=86400, immutable\r\n",
        "Server-Timing: eval;dur=1.500000, encode;dur=0.250000\r\n", "Content-Length: 9\r\n"})
    EXPECT_NE(fields.find(field), std::string::npos) << field << " in " << fields;

  const http::Response r = tileResponse({tile, TileStatus::kOk, {}});
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.route, "tile");
  ASSERT_TRUE(r.sharedBody);
  EXPECT_EQ(r.sharedBody.get(), &tile->bytes); // aliases the cache: no copy per request
  ASSERT_TRUE(r.preparedFields);
  EXPECT_EQ(r.preparedFields.get(), &tile->httpFields);
}

TEST(TileResponse, AnOkTileWithoutPreparedFieldsGetsTheSameHeaders) {
  auto tile = std::make_shared<service::CachedTile>();
  tile->bytes = "x";
  tile->mimeType = "model/gltf-binary";
  tile->etag = "\"e\"";
  const http::Response r = tileResponse({tile, TileStatus::kOk, {}});
  EXPECT_EQ(r.status, 200);
  EXPECT_FALSE(r.preparedFields);
  EXPECT_EQ(header(r, "Content-Type"), "model/gltf-binary");
  EXPECT_EQ(header(r, "ETag"), "\"e\"");
  EXPECT_EQ(header(r, "Cache-Control"), "public, max-age=86400, immutable");
  EXPECT_EQ(header(r, "Server-Timing"), "eval;dur=0.000000, encode;dur=0.000000");
}

TEST(TileResponse, EtagIsFnv1aOfWorldKeyAndTileKey) {
  // Golden: FNV-1a 64 of "k|island|tiles|10|433|373|png|0", as served since the first release.
  EXPECT_EQ(tileEtag("k", "island|tiles|10|433|373|png|0"), "\"a8b70f5f522bc1e3\"");
  EXPECT_NE(tileEtag("k", "island|tiles|10|433|373|png|0"),
            tileEtag("k2", "island|tiles|10|433|373|png|0"));
}

TEST(TileResponse, IfNoneMatchListsAndWildcardMatch) {
  const std::string etag = "\"a8b70f5f522bc1e3\"";
  EXPECT_TRUE(etagMatches(etag, etag));
  EXPECT_TRUE(etagMatches("*", etag));
  EXPECT_TRUE(etagMatches("\"other\", \t" + etag + " ", etag));
  EXPECT_FALSE(etagMatches("", etag));
  EXPECT_FALSE(etagMatches("\"other\"", etag));
  EXPECT_FALSE(etagMatches("W/" + etag, etag));
  const http::Response r = notModified(etag);
  EXPECT_EQ(r.status, 304);
  EXPECT_EQ(r.route, "tile");
  EXPECT_EQ(header(r, "ETag"), etag);
  EXPECT_EQ(header(r, "Cache-Control"), "public, max-age=86400, immutable");
  EXPECT_TRUE(r.body.empty());
  // Asked for without the world's current version: revalidated after a minute.
  EXPECT_EQ(header(notModified(etag, "", false), "Cache-Control"),
            "public, max-age=60, must-revalidate");
}

TEST(TileResponse, OnlyTheCurrentVersionIsImmutable) {
  auto tile = std::make_shared<service::CachedTile>();
  tile->bytes = "bytes";
  tile->mimeType = "image/png";
  tile->etag = "\"e\"";
  const http::Response current = tileResponse({tile, TileStatus::kOk, {}}, true);
  const http::Response other = tileResponse({tile, TileStatus::kOk, {}}, false);
  EXPECT_EQ(header(current, "Cache-Control"), "public, max-age=86400, immutable");
  EXPECT_EQ(header(other, "Cache-Control"), "public, max-age=60, must-revalidate");
  EXPECT_EQ(header(other, "ETag"), "\"e\"");
}

} // namespace
} // namespace strahler::app
