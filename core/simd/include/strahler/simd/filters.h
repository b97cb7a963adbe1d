#pragma once

#include "strahler/simd/instruction_set.h"
#include "strahler/simd/lanes.h"

#include <cstddef>
#include <cstdint>
#include <span>

// Stream compaction: filters that keep, in order, the entries passing a test, with vector
// instructions of `set` where it has a kernel for them (AVX2, AVX-512), else the portable code
// (no branch per entry); every set keeps the same entries. `set` must be supported
// (supports()).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace strahler::simd {

/// Entries a filter may write past the last one it keeps (vector stores write whole vectors).
inline constexpr std::size_t kFilterOverrun = 16;

/// Copies, in order, each ids[k] whose keys[k] lies in [low, high] to `out` and returns how
/// many it kept. `out` must have room for keys.size() + kFilterOverrun ids.
std::size_t keepWithin(std::span<const float> keys, const std::uint32_t* ids, float low, float high,
                       std::uint32_t* out, InstructionSet set);

/// Discs in columns (index: id): centres (x, y), squared reaches, and a key per disc.
struct DiscColumns {
  const double* x = nullptr;
  const double* y = nullptr;
  const double* reach2 = nullptr;
  const float* key = nullptr;
};

/// An axis-aligned box by its corners.
struct Box {
  double minX = 0.0, minY = 0.0, maxX = 0.0, maxY = 0.0;
};

/// How far (x, y) lies outside `box` along x (lane 0) and y (lane 1): each the larger of
/// min − p and p − max, at least 0 (infinite for an empty box). In a vector of two lanes: GCC
/// compiles a scalar maximum with 0 to a branch, which tests of many boxes mispredict about
/// every other time.
inline Vectors<2>::Doubles gapsToBox(double x, double y, const Box& box) noexcept {
  using Pair = Vectors<2>::Doubles;
  const Pair point{x, y};
  const Pair below = Pair{box.minX, box.minY} - point, above = point - Pair{box.maxX, box.maxY};
  const Pair gap = below > above ? below : above;
  return gap > 0.0 ? gap : Pair{};
}

/// Writes, in order, each id of first, first + 1, … first + count − 1 whose disc meets `box`
/// (gx² + gy² ≤ reach2 with (gx, gy) = gapsToBox() of its centre) to `ids` and its key to
/// `keys`, and returns how many it kept. `ids` and `keys` must have room for
/// count + kFilterOverrun entries.
std::size_t keepDiscsMeeting(const DiscColumns& discs, std::uint32_t first, std::size_t count,
                             const Box& box, std::uint32_t* ids, float* keys, InstructionSet set);

} // namespace strahler::simd

#pragma GCC diagnostic pop
