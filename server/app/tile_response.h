#pragma once

#include "tile_cache.h"
#include "tile_renderer.h"

#include "strahler/http/http_types.h"

#include <memory>
#include <string>

namespace strahler::app {

/// The strong ETag of a tile: "\"" + 16 hex digits of FNV-1a(worldKey + "|" + tileKey) + "\"",
/// from its world's cache key and its tileKey().
std::string tileEtag(const std::string& worldKey, const std::string& tileKey);

/// True when an If-None-Match value (a list, or "*") names `etag`.
bool etagMatches(const std::string& ifNoneMatch, const std::string& etag);

/// The 304 answering a conditional request for the tile of `etag`.
http::Response notModified(const std::string& etag);

/// `tile` as the cache keeps it, with its ETag and the header fields of its 200 response
/// prepared once, so that every answer from the cache formats and copies nothing. `vary` names
/// the request header fields the bytes were chosen by ("" for none).
std::shared_ptr<const service::CachedTile> cachedTile(RenderedTile tile, const std::string& etag,
                                                      const std::string& vary = {});

/// The one mapping from a tile's outcome to HTTP: kOk → 200 with the tile (Content-Type, ETag,
/// immutable Cache-Control, Server-Timing), kNotFound → 404, kUnsupported → 501, kRetryLater →
/// 503 with Retry-After: 1, kFailed → 500; the errors carry the outcome's message as JSON.
/// Route label "tile".
http::Response tileResponse(const service::TileCache::Outcome& outcome);

} // namespace strahler::app
