#include "strahler/store/world_cache.h"

#include "strahler/store/cache_key.h"
#include "strahler/store/world_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace strahler::store {
namespace {

using construction::WorldData;

base::Error invalidKey(std::string_view key) {
  return base::makeError(base::ErrorCode::kInvalidInput,
                         "invalid world cache key '" + std::string(key) +
                             "' (1 to 128 characters among 0-9, A-Z, a-z, '_' and '-')");
}

/// Moves a bad cache file out of the way (or deletes it) and says why in *warning.
std::optional<WorldData> discard(const std::string& path, const std::string& reason,
                                 std::string* warning) {
  std::string note = "ignoring corrupt cached world: " + reason;
  const std::string aside = path + ".corrupt";
  if (std::rename(path.c_str(), aside.c_str()) == 0) {
    note += "; moved to '" + aside + "'";
  } else {
    const int renameError = errno;
    if (::unlink(path.c_str()) == 0)
      note += "; deleted it (cannot rename: " + std::string(std::strerror(renameError)) + ")";
    else
      note += "; cannot move it aside: " + std::string(std::strerror(renameError));
  }
  if (warning != nullptr)
    *warning = note + "; regenerating";
  return std::nullopt;
}

} // namespace

WorldCache::WorldCache(std::string dir) : dir_(std::move(dir)) {}

std::string WorldCache::pathFor(std::string_view key) const {
  return (std::filesystem::path(dir_) / (std::string(key) + ".world")).string();
}

base::Result<std::optional<WorldData>> WorldCache::load(std::string_view key,
                                                        std::string* warning) {
  if (!isValidCacheKey(key))
    return invalidKey(key);
  const std::string path = pathFor(key);
  auto world = readWorldFile(path);
  if (world.ok()) {
    if (world.value().cacheKey == key)
      return std::optional<WorldData>(std::move(world).value());
    return discard(path,
                   "world file '" + path + "' holds cache key '" + world.value().cacheKey +
                       "', not '" + std::string(key) + "'",
                   warning);
  }
  switch (world.error().code) {
  case base::ErrorCode::kNotFound:
    return std::optional<WorldData>();
  case base::ErrorCode::kCorrupt:
    return discard(path, world.error().message, warning);
  default:
    return std::move(world).error();
  }
}

base::Status WorldCache::save(const WorldData& world) {
  if (!isValidCacheKey(world.cacheKey))
    return invalidKey(world.cacheKey);
  if (!dir_.empty()) {
    std::error_code error;
    std::filesystem::create_directories(dir_, error);
    if (error)
      return base::makeError(base::ErrorCode::kIoError,
                             "cannot create the world cache directory '" + dir_ +
                                 "': " + error.message());
  }
  return writeWorldFile(pathFor(world.cacheKey), world);
}

} // namespace strahler::store
