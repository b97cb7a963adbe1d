#pragma once
// Synthetic, valid WorldData for the store tests (every value on its quantum grid), plus
// field-by-field comparison, error matchers and scratch directories.

#include "result_matchers.h"

#include "strahler/base/result.h"
#include "strahler/construction/world_data.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace strahler::store::test_support {

/// A small world: 2 polygons (one with a lake), 2 trees of 12 nodes, a few primitives per
/// block (some blocks empty), one river primitive without a node, stage times (which files do not
/// store).
construction::WorldData makeSmallWorld(std::uint64_t seed = 1);

/// A world of realistic density over `areaKm2` of land: one node per km², 10 terrain
/// primitives per block at ~300 m spacing with elevations in 0-800 m, one river primitive of
/// 15 curve points per block.
construction::WorldData makeLargeWorld(double areaKm2 = 1000.0, std::uint64_t seed = 7);

/// Passes when every stored field of `a` equals that of `b` (doubles compared with ==; stage
/// times are not stored).
::testing::AssertionResult worldsEqual(const construction::WorldData& a,
                                       const construction::WorldData& b);

using strahler::test_support::failsWith; // tests/support/result_matchers.h

/// A fresh, empty directory under the build tree named after the running test.
std::string scratchDir();

/// Names of the entries of `dir`, sorted.
std::vector<std::string> listDir(const std::string& dir);

} // namespace strahler::store::test_support
