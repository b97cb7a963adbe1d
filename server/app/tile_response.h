#pragma once

#include "tile_cache.h"
#include "tile_renderer.h"

#include "strahler/http/http_types.h"

#include <memory>
#include <string>

namespace strahler::app {

/// The strong ETag of a tile: "\"" + 16 hex digits of FNV-1a(worldVersion + "|" + tileKey) +
/// "\"", from its world's content version (worldVersion()) and its tileKey(): a function of the
/// bytes, so a regenerated world's tiles never match an old ETag.
std::string tileEtag(const std::string& worldVersion, const std::string& tileKey);

/// The Cache-Control of a resource of one world's content (its tiles, its rivers):
/// "public, max-age=86400, immutable" when the URL carried the world's current version, else
/// "public, max-age=60, must-revalidate".
const char* tileCacheControl(bool currentVersion);

/// True when an If-None-Match value (a list, or "*") names `etag`.
bool etagMatches(const std::string& ifNoneMatch, const std::string& etag);

/// The 304 answering a conditional request for the tile of `etag` (with the Vary of its 200,
/// `vary`, when not empty), with the Cache-Control of tileResponse(…, currentVersion).
http::Response notModified(const std::string& etag, const std::string& vary = {},
                           bool currentVersion = true);

/// `tile` as the cache keeps it, with its ETag and the header fields of its 200 response
/// prepared once, so that every answer from the cache formats and copies nothing. `vary` names
/// the request header fields the bytes were chosen by ("" for none).
std::shared_ptr<const service::CachedTile> cachedTile(RenderedTile tile, const std::string& etag,
                                                      const std::string& vary = {});

/// The one mapping from a tile's outcome to HTTP: kOk → 200 with the tile (Content-Type, ETag,
/// Cache-Control, Server-Timing), kNotFound → 404, kUnsupported → 501, kRetryLater → 503 with
/// Retry-After: 1, kFailed → 500; the errors carry the outcome's message as JSON. Cache-Control
/// is "public, max-age=86400, immutable" when the URL carried the world's current version
/// (`currentVersion`), else "public, max-age=60, must-revalidate". Route label "tile".
http::Response tileResponse(const service::TileCache::Outcome& outcome, bool currentVersion = true);

} // namespace strahler::app
