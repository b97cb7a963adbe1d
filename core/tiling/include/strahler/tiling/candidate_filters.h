#pragma once

#include "strahler/geometry/aabb.h"
#include "strahler/primitives/terrain_primitive.h"
#include "strahler/simd/filters.h"
#include "strahler/simd/instruction_set.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace strahler::tiling {

// Filters of candidate lists for tile binning: each keeps, in order, the candidates that pass
// a test, by simd's filters (strahler/simd/filters.h: vector instructions of `set` where it
// has a kernel for them, else portable code); every set keeps the same candidates. `set` must
// be one this CPU has.

/// Entries a filter may write past the last one it keeps (vector stores write whole vectors).
inline constexpr std::size_t kFilterOverrun = simd::kFilterOverrun;

/// Copies, in order, each ids[k] whose keys[k] lies in [low, high] to `out` and returns how
/// many it kept. `out` must have room for keys.size() + kFilterOverrun ids.
std::size_t keepKeysWithin(std::span<const float> keys, const std::uint32_t* ids, float low,
                           float high, std::uint32_t* out,
                           simd::InstructionSet set = simd::instructionSet());

/// Terrain primitives' discs in columns (index: primitive id), as binning reads them: centre,
/// squared radius with a relative slack of 1e-9 (extra candidates are harmless: w = 0 beyond
/// the radius), and the centre's y rounded to float (the key of keepKeysWithin()).
struct TerrainDiscs {
  std::vector<double> x, y, reach2;
  std::vector<float> keyY;
  /// The discs of `terrain`.
  explicit TerrainDiscs(std::span<const primitives::TerrainPrimitive> terrain);
  /// Disc i's centre.
  geometry::Vec2 center(std::uint32_t i) const noexcept { return {x[i], y[i]}; }
};

/// Writes, in order, each id of first, first + 1, … first + count − 1 whose disc meets `box`
/// (its centre's squared distance to the box at most its reach2, computed as
/// squaredDistanceToBox() does) to `ids` and its key to `keys`, and returns how many it kept.
/// `ids` and `keys` must have room for count + kFilterOverrun entries.
std::size_t keepDiscsMeeting(const TerrainDiscs& discs, std::uint32_t first, std::size_t count,
                             const geometry::Aabb& box, std::uint32_t* ids, float* keys,
                             simd::InstructionSet set = simd::instructionSet());

/// How far p lies outside box b along x and along y: each the larger of b.min − p and
/// p − b.max, at least 0 (infinite for an empty box).
inline geometry::Vec2 gapsToBox(geometry::Vec2 p, const geometry::Aabb& b) noexcept {
  const auto gap = simd::gapsToBox(p.x, p.y, {b.min.x, b.min.y, b.max.x, b.max.y});
  return {gap[0], gap[1]};
}
/// The squared distance from p to box b: the gaps squared and added.
inline double squaredDistanceToBox(geometry::Vec2 p, const geometry::Aabb& b) noexcept {
  const geometry::Vec2 gap = gapsToBox(p, b);
  return gap.x * gap.x + gap.y * gap.y;
}

} // namespace strahler::tiling
