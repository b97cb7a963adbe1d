#pragma once

#include <optional>
#include <string>

namespace strahler::app {

/// The folder of the built viewer (index.html, game.html, src/) that `serve` publishes:
/// `explicitRoot` (--web-root) when given; else the installed one relative to the running
/// program (bin/../share/strahler/web after `cmake --install` or the Debian package); else the
/// build's source tree (web/dist). Never relative to the current directory. "" when none holds
/// an index.html.
std::string findWebRoot(const std::optional<std::string>& explicitRoot);

} // namespace strahler::app
