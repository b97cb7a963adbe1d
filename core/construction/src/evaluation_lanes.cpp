#include "evaluation_lanes.h"

#include "strahler/base/lanes.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

// Kernels pass kLanes-wide vectors between inlined functions; the ABI note does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace strahler::construction {
namespace detail {
namespace {

namespace baseline { // SSE2, every x86-64
#include "evaluation_kernels.inc"
} // namespace baseline

#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
#include "evaluation_kernels.inc"
} // namespace avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq")
namespace avx512 {
#include "evaluation_kernels.inc"
} // namespace avx512
#pragma GCC pop_options

bool supported(InstructionSet set) noexcept {
  switch (set) {
  case InstructionSet::kAvx512:
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
  case InstructionSet::kAvx2:
    return __builtin_cpu_supports("avx2");
  case InstructionSet::kBaseline:
    return true;
  }
  return false;
}

InstructionSet widest() noexcept {
  for (InstructionSet set : {InstructionSet::kAvx512, InstructionSet::kAvx2})
    if (supported(set))
      return set;
  return InstructionSet::kBaseline;
}

std::atomic<InstructionSet>& current() noexcept {
  static std::atomic<InstructionSet> set{widest()};
  return set;
}

/// Runs the build of a kernel for the instruction set in use.
template <class R, class Args>
R runBuild(R (*base)(const Args&) noexcept, R (*withAvx2)(const Args&) noexcept,
           R (*withAvx512)(const Args&) noexcept, const Args& args) noexcept {
  switch (current().load(std::memory_order_relaxed)) {
  case InstructionSet::kAvx512:
    return withAvx512(args);
  case InstructionSet::kAvx2:
    return withAvx2(args);
  case InstructionSet::kBaseline:
    break;
  }
  return base(args);
}

} // namespace

bool closestOnCurveLanes(const CurveLaneArgs& args) noexcept {
  return runBuild(baseline::curveLanes, avx2::curveLanes, avx512::curveLanes, args);
}

bool closestOnCurvePoint(const CurveLaneArgs& args) noexcept {
  return baseline::curveKernel<baseline::Single>(args);
}

void terrainLanes(const TerrainLaneArgs& args) noexcept {
  // Two functions, not one: in a single function GCC keeps the sums' accumulators on the
  // stack (the noise needs many registers), and every candidate then waits on a store.
  runBuild(baseline::terrainSumsLanes, avx2::terrainSumsLanes, avx512::terrainSumsLanes, args);
  runBuild(baseline::terrainNoiseLanes, avx2::terrainNoiseLanes, avx512::terrainNoiseLanes, args);
}

void terrainPoint(const TerrainLaneArgs& args) noexcept {
  baseline::terrainKernel<baseline::Single>(args);
}

void nearestSegmentLanes(const SegmentLaneArgs& args) noexcept {
  runBuild(baseline::nearestSegmentsLanes, avx2::nearestSegmentsLanes, avx512::nearestSegmentsLanes,
           args);
}

} // namespace detail

InstructionSet instructionSet() noexcept {
  return detail::current().load(std::memory_order_relaxed);
}

bool useInstructionSet(InstructionSet set) noexcept {
  if (!detail::supported(set))
    return false;
  detail::current().store(set, std::memory_order_relaxed);
  return true;
}

} // namespace strahler::construction
