#pragma once

#include <string>
#include <vector>

namespace strahler::app {

/// `strahler info WORLD`: the world's statistics as JSON. Returns the exit code.
int runInfo(const std::vector<std::string>& args);
/// `strahler render WORLD [--size N] -o overview.png`: a shaded-relief picture.
int runRender(const std::vector<std::string>& args);
/// `strahler tile WORLD --scheme web|local --z Z --x X --y Y --format F [--size N] -o FILE`.
int runTile(const std::vector<std::string>& args);
/// `strahler analyze WORLD [--cell-size M]`: drainage, river profiles, Horton ratios as JSON.
int runAnalyze(const std::vector<std::string>& args);

} // namespace strahler::app
