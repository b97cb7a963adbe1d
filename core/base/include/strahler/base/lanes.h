#pragma once

// Forwards to strahler/simd/lanes.h, where the lane types live now, for the files that still
// name them base::kLanes and base::Vectors (core/tiling's tile_evaluator.cpp, bins.h, bins.cpp
// and tests/core/tiling/bins_test.cpp, which link strahler::simd); new code includes
// strahler/simd/lanes.h. base itself has no vector code.
#include "strahler/simd/lanes.h"

namespace strahler::base {

using simd::Doubles;
using simd::kLanes;
using simd::Vectors;

} // namespace strahler::base
