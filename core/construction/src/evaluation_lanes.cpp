#include "evaluation_lanes.h"

#include "folds.h"

#include "strahler/simd/instruction_set.h"
#include "strahler/simd/lane_ops.h"
#include "strahler/simd/lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

// Kernels pass kLanes-wide vectors between inlined functions; the ABI note does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace strahler::construction {
namespace detail {
namespace {

using simd::InstructionSet;

// Without x86 intrinsics (STRAHLER_SIMD_X86 0), the baseline builds alone, with the portable
// operations: the same bits.
namespace baseline { // SSE2, every x86-64: two doubles per register
#define STRAHLER_KERNEL_WIDTH 2
#if STRAHLER_SIMD_X86
#define STRAHLER_KERNEL_MASK_SSE2
#endif
#include "evaluation_kernels.inc"
#undef STRAHLER_KERNEL_MASK_SSE2
#undef STRAHLER_KERNEL_WIDTH
} // namespace baseline

// SSE2 again with vectors of eight: the noise's 32-bit multiplications and gradient lookups
// cost less split over four registers than done two lanes at a time (measured: zoom 18 tiles
// 35 → 14 ms); every other kernel is faster two lanes at a time.
namespace baselineNoise {
#define STRAHLER_KERNEL_WIDTH 8
#include "evaluation_kernels.inc"
#undef STRAHLER_KERNEL_WIDTH
} // namespace baselineNoise

#if STRAHLER_SIMD_X86
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 { // four doubles per register
#define STRAHLER_KERNEL_WIDTH 4
#define STRAHLER_KERNEL_MASK_AVX2
#include "evaluation_kernels.inc"
#undef STRAHLER_KERNEL_MASK_AVX2
#undef STRAHLER_KERNEL_WIDTH
} // namespace avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq")
namespace avx512 { // eight doubles per register
#define STRAHLER_KERNEL_WIDTH 8
#define STRAHLER_KERNEL_WIDE_HASH
#define STRAHLER_KERNEL_MASK_AVX512
#include "evaluation_kernels.inc"
#undef STRAHLER_KERNEL_MASK_AVX512
#undef STRAHLER_KERNEL_WIDE_HASH
#undef STRAHLER_KERNEL_WIDTH
} // namespace avx512
#pragma GCC pop_options
#endif // STRAHLER_SIMD_X86

/// Runs the build of a kernel for the instruction set in use.
template <class R, class Args>
R runBuild(R (*base)(const Args&) noexcept, R (*withAvx2)(const Args&) noexcept,
           R (*withAvx512)(const Args&) noexcept, const Args& args) noexcept {
  switch (simd::instructionSet()) {
  case InstructionSet::kAvx512:
    return withAvx512(args);
  case InstructionSet::kAvx2:
    return withAvx2(args);
  case InstructionSet::kBaseline:
    break;
  }
  return base(args);
}
#if !STRAHLER_SIMD_X86
/// The portable build's only kernels (simd::instructionSet() is then always kBaseline).
namespace avx2 = baseline;
namespace avx512 = baseline;
#endif

} // namespace

void riversLanes(const RiverLaneArgs& args) noexcept {
  runBuild(baseline::riversLanes, avx2::riversLanes, avx512::riversLanes, args);
}

void riversPoint(const RiverLaneArgs& args) noexcept {
  baseline::riversKernel<baseline::Single>(args, 0);
}

void terrainLanes(const TerrainLaneArgs& args) noexcept {
  // Two functions, not one: in a single function GCC keeps the sums' accumulators on the
  // stack (the noise needs many registers), and every candidate then waits on a store.
  runBuild(baseline::terrainSumsLanes, avx2::terrainSumsLanes, avx512::terrainSumsLanes, args);
  runBuild(baselineNoise::terrainNoiseLanes, avx2::terrainNoiseLanes, avx512::terrainNoiseLanes,
           args);
}

void terrainPoint(const TerrainLaneArgs& args) noexcept {
  baseline::terrainKernel<baseline::Single>(args);
}

void coastLanes(const CoastLaneArgs& args) noexcept {
  runBuild(baseline::coastLanes, avx2::coastLanes, avx512::coastLanes, args);
}

double coastPoint(Sample terrain, Sample rivers, bool onLand, double shore) noexcept {
  return baseline::coastKernel<baseline::Single>(terrain.h, terrain.w, rivers.h, rivers.w, onLand,
                                                 shore);
}

double farSeaPoint(Sample rivers) noexcept {
  static const double floor = baseline::shelfDepth<baseline::Single>(CoastShape::kShelfReach);
  return baseline::seaBed<baseline::Single>(floor, rivers.h, rivers.w);
}

void nearestSegmentLanes(const SegmentLaneArgs& args) noexcept {
  runBuild(baseline::nearestSegmentsLanes, avx2::nearestSegmentsLanes, avx512::nearestSegmentsLanes,
           args);
}

void insideLanes(const InsideLaneArgs& args) noexcept {
  runBuild(baseline::insidesLanes, avx2::insidesLanes, avx512::insidesLanes, args);
}

} // namespace detail

} // namespace strahler::construction
