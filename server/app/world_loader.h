#pragma once

#include "strahler/base/result.h"
#include "strahler/base/stage_timer.h"
#include "strahler/construction/world_data.h"
#include "strahler/input/world_spec.h"

#include <string>
#include <vector>

namespace strahler::app {

/// A world obtained from the cache or freshly generated (and then cached).
struct LoadedWorld {
  construction::WorldData data;
  bool fromCache = false;            ///< True when read from the cache instead of generated.
  std::string path;                  ///< The cache file that holds it.
  std::vector<std::string> warnings; ///< E.g. a corrupt cache file that was set aside.
};

/// The cache directory: $STRAHLER_CACHE_DIR, else $XDG_CACHE_HOME/strahler, else
/// $HOME/.cache/strahler, else ./strahler-cache.
std::string defaultCacheDir();

/// Loads the world of `spec` from `cacheDir`, or generates and caches it. A damaged cache
/// file is reported in warnings and regenerated, never used.
base::Result<LoadedWorld> loadOrGenerateWorld(const input::WorldSpec& spec,
                                              const std::string& cacheDir,
                                              const base::ProgressCallback& progress,
                                              base::StageTimer* timer);

} // namespace strahler::app
