#pragma once

#include <string>
#include <vector>

namespace strahler::app {

/// `strahler generate`: builds a world from a coastline and reports it. Returns the exit
/// code (0 ok, 1 bad input or failure, 2 bad usage).
int runGenerate(const std::vector<std::string>& args);

/// Usage text of `strahler generate`.
const char* generateUsage() noexcept;

} // namespace strahler::app
