#pragma once

#include "strahler/input/world_spec.h"

#include <string>

namespace strahler::test_support {

/// The embedded default island with default params (and `seed`).
input::WorldSpec defaultIslandSpec(std::uint64_t seed = 1);
/// Mallorca (Natural Earth 1:10m, ~3,640 km²) with default params.
input::WorldSpec mallorcaSpec(std::uint64_t seed = 1);
/// Mallorca scaled by `scale` in each direction about its local frame's centre (scale² times
/// the area: a large island with Mallorca's shape), default params.
input::WorldSpec scaledMallorcaSpec(double scale, std::uint64_t seed = 1);
/// Corsica (Natural Earth 1:10m, ~8,700 km²) with default params.
input::WorldSpec corsicaSpec(std::uint64_t seed = 1);
/// Contents of a file in tests/data.
std::string readTestData(const std::string& name);

} // namespace strahler::test_support
