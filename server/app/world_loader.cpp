#include "world_loader.h"

#include "strahler/construction/world_builder.h"
#include "strahler/store/cache_key.h"
#include "strahler/store/world_cache.h"

#include <cstdlib>

namespace strahler::app {

std::string defaultCacheDir() {
  if (const char* dir = std::getenv("STRAHLER_CACHE_DIR"); dir && *dir)
    return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::string(xdg) + "/strahler";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::string(home) + "/.cache/strahler";
  return "strahler-cache";
}

base::Result<LoadedWorld> loadOrGenerateWorld(const input::WorldSpec& spec,
                                              const std::string& cacheDir,
                                              const base::ProgressCallback& progress,
                                              base::StageTimer* timer) {
  LoadedWorld out;
  const std::string key = store::cacheKey(spec, construction::kGeneratorVersion);
  store::WorldCache cache(cacheDir);
  out.path = cache.pathFor(key);
  if (timer)
    timer->start("load");
  std::string warning;
  STRAHLER_ASSIGN_OR_RETURN(std::optional<construction::WorldData> cached,
                            cache.load(key, &warning));
  if (!warning.empty())
    out.warnings.push_back(warning);
  if (cached) {
    out.data = std::move(*cached);
    out.data.name = spec.name; // the same world may be cached under another file's name
    out.fromCache = true;
    if (timer)
      timer->finish();
    return out;
  }
  STRAHLER_ASSIGN_OR_RETURN(out.data, construction::generateWorldData(spec, key, progress, timer));
  if (timer)
    timer->start("save");
  STRAHLER_RETURN_IF_ERROR(cache.save(out.data));
  if (timer)
    timer->finish();
  return out;
}

} // namespace strahler::app
