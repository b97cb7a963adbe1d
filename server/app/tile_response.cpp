#include "tile_response.h"

#include <cstdint>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

namespace strahler::app {
namespace {

/// A tile asked for by its world's current version: that URL names these bytes for ever.
constexpr const char* kTileCacheControl = "public, max-age=86400, immutable";
/// A tile asked for without the version, or with another one: the same URL may name other
/// bytes once the world is regenerated, so caches keep it briefly and then revalidate (its
/// ETag follows the content, so an old one is never answered 304).
constexpr const char* kUnversionedTileCacheControl = "public, max-age=60, must-revalidate";

constexpr std::uint64_t kFnvOffset = 1469598103934665603ull;

/// FNV-1a of `text`, continuing from `h` (so that hashing parts equals hashing their concat).
std::uint64_t fnv1a(std::string_view text, std::uint64_t h = kFnvOffset) {
  for (unsigned char c : text)
    h = (h ^ c) * 1099511628211ull;
  return h;
}

/// Header fields of a tile's 200 response.
std::vector<std::pair<std::string, std::string>> tileHeaders(const service::CachedTile& t,
                                                             bool currentVersion) {
  std::vector<std::pair<std::string, std::string>> headers = {
      {"Content-Type", t.mimeType},
      {"ETag", t.etag},
      {"Cache-Control", tileCacheControl(currentVersion)},
      {"Server-Timing",
       "eval;dur=" + std::to_string(t.evaluateMs) + ", encode;dur=" + std::to_string(t.encodeMs)}};
  if (!t.contentEncoding.empty())
    headers.emplace_back("Content-Encoding", t.contentEncoding);
  if (!t.vary.empty())
    headers.emplace_back("Vary", t.vary);
  return headers;
}

/// The HTTP status of an outcome without a tile.
int errorStatus(service::TileStatus status) {
  switch (status) {
  case service::TileStatus::kNotFound:
    return 404;
  case service::TileStatus::kUnsupported:
    return 501;
  case service::TileStatus::kRetryLater:
    return 503;
  case service::TileStatus::kOk: // an ok without a tile: the cache calls it a failure too
  case service::TileStatus::kFailed:
    break;
  }
  return 500;
}

} // namespace

const char* tileCacheControl(bool currentVersion) {
  return currentVersion ? kTileCacheControl : kUnversionedTileCacheControl;
}

std::string tileEtag(const std::string& worldVersion, const std::string& tileKey) {
  std::uint64_t h = fnv1a(tileKey, fnv1a("|", fnv1a(worldVersion)));
  std::string etag(18, '"');
  for (int i = 16; i >= 1; --i, h >>= 4)
    etag[static_cast<std::size_t>(i)] = "0123456789abcdef"[h & 0xF];
  return etag;
}

bool etagMatches(const std::string& ifNoneMatch, const std::string& etag) {
  if (ifNoneMatch.empty())
    return false;
  if (ifNoneMatch == "*")
    return true;
  std::stringstream list(ifNoneMatch);
  std::string item;
  while (std::getline(list, item, ',')) {
    const auto b = item.find_first_not_of(" \t");
    const auto e = item.find_last_not_of(" \t");
    if (b != std::string::npos && item.substr(b, e - b + 1) == etag)
      return true;
  }
  return false;
}

http::Response notModified(const std::string& etag, const std::string& vary, bool currentVersion) {
  http::Response r;
  r.status = 304;
  r.headers = {{"ETag", etag}, {"Cache-Control", tileCacheControl(currentVersion)}};
  if (!vary.empty())
    r.headers.emplace_back("Vary", vary);
  r.route = "tile";
  return r;
}

std::shared_ptr<const service::CachedTile> cachedTile(RenderedTile tile, const std::string& etag,
                                                      const std::string& vary) {
  auto t = std::make_shared<service::CachedTile>();
  t->bytes = std::move(tile.bytes);
  t->bytes.shrink_to_fit(); // the cache charges capacity: keep no encoder reservation
  // Copied, not moved: the cache charges these strings' capacity as copy-assignment sizes it.
  t->mimeType = tile.mimeType;
  t->etag = etag;
  t->contentEncoding = tile.contentEncoding;
  t->vary = vary;
  t->evaluateMs = tile.evaluateMs;
  t->encodeMs = tile.encodeMs;
  http::Response plain;
  plain.headers = tileHeaders(*t, true);
  plain.sharedBody = std::shared_ptr<const std::string>(t, &t->bytes);
  t->httpFields = http::prepareFields(plain);
  t->httpFields.shrink_to_fit();
  return t;
}

http::Response tileResponse(const service::TileCache::Outcome& outcome, bool currentVersion) {
  if (outcome.status != service::TileStatus::kOk || !outcome.tile) {
    const int status = errorStatus(outcome.status);
    http::Response r = http::errorResponse(status, outcome.message);
    if (status == 503)
      r.headers.emplace_back("Retry-After", "1");
    r.route = "tile";
    return r;
  }
  // The bytes and prepared header fields (those of the current version) alias the cached tile:
  // a hit by a versioned URL formats and copies nothing.
  const std::shared_ptr<const service::CachedTile>& tile = outcome.tile;
  http::Response r;
  r.sharedBody = std::shared_ptr<const std::string>(tile, &tile->bytes);
  if (tile->httpFields.empty() || !currentVersion) {
    r.headers = tileHeaders(*tile, currentVersion);
  } else {
    r.preparedFields = std::shared_ptr<const std::string>(tile, &tile->httpFields);
  }
  r.route = "tile";
  return r;
}

} // namespace strahler::app
