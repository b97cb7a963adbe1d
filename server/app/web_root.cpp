#include "web_root.h"

#include <filesystem>
#include <system_error>

namespace strahler::app {

std::string findWebRoot(const std::optional<std::string>& explicitRoot) {
  namespace fs = std::filesystem;
  if (explicitRoot)
    return *explicitRoot;
  std::error_code ec;
  const fs::path program = fs::read_symlink("/proc/self/exe", ec);
  fs::path candidates[2];
  if (!ec && !program.empty())
    candidates[0] = (program.parent_path() / STRAHLER_WEB_INSTALL_DIR).lexically_normal();
  candidates[1] = STRAHLER_WEB_BUILD_DIR;
  for (const fs::path& folder : candidates)
    if (!folder.empty() && fs::exists(folder / "index.html", ec))
      return folder.string();
  return "";
}

} // namespace strahler::app
