#pragma once

#include <string>
#include <vector>

namespace strahler::app {

/// `strahler serve`: serves worlds over HTTP until SIGINT/SIGTERM. Returns the exit code.
int runServe(const std::vector<std::string>& args);

} // namespace strahler::app
