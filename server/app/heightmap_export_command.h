#pragma once

#include <string>
#include <vector>

namespace strahler::app {

/// `strahler export-heightmap WORLD.world --engine unity|unreal|godot|raw --size N -o PATH
/// ...`: one 16-bit heightmap of a box of the world (or Unreal's tiles of it) at an engine's
/// size, byte order and orientation, with a sidecar JSON of the engine's import numbers.
/// Returns the exit code: 0, 1 (failure), 2 (bad command line), or death by the signal that
/// interrupted it.
int runExportHeightmap(const std::vector<std::string>& args);

} // namespace strahler::app
