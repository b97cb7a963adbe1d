#pragma once

#include "strahler/input/world_spec.h"

#include <string>
#include <string_view>

namespace strahler::store {

/// Cache key of the world `spec` generates under `generatorVersion`: 32 lower-case hex digits
/// (128 bits: FNV-1a 64 and a splitmix64 word hash) of a canonical text made of
/// canonicalJson(params), every land vertex in lon/lat (shortest round-trip decimals), the
/// user mouths, each constraint map (kind, bounds, size, hash of its pixels) and the
/// generator version. The same on every machine; the world's name is not part of it.
std::string cacheKey(const input::WorldSpec& spec, std::string_view generatorVersion);

/// The canonical text cacheKey hashes (exposed for diagnostics and tests).
std::string canonicalSpecText(const input::WorldSpec& spec, std::string_view generatorVersion);

/// True when `key` can name a cache file: 1 to 128 characters from [0-9A-Za-z_-].
bool isValidCacheKey(std::string_view key) noexcept;

} // namespace strahler::store
