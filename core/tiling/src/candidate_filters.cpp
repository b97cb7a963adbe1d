#include "strahler/tiling/candidate_filters.h"

#include "strahler/simd/filters.h"

namespace strahler::tiling {

std::size_t keepKeysWithin(std::span<const float> keys, const std::uint32_t* ids, float low,
                           float high, std::uint32_t* out, simd::InstructionSet set) {
  return simd::keepWithin(keys, ids, low, high, out, set);
}

TerrainDiscs::TerrainDiscs(std::span<const primitives::TerrainPrimitive> terrain) {
  for (const primitives::TerrainPrimitive& t : terrain) {
    x.push_back(t.center.x);
    y.push_back(t.center.y);
    reach2.push_back(t.radius * t.radius * (1.0 + 1e-9));
    keyY.push_back(static_cast<float>(t.center.y));
  }
}

std::size_t keepDiscsMeeting(const TerrainDiscs& discs, std::uint32_t first, std::size_t count,
                             const geometry::Aabb& box, std::uint32_t* ids, float* keys,
                             simd::InstructionSet set) {
  return simd::keepDiscsMeeting(
      {discs.x.data(), discs.y.data(), discs.reach2.data(), discs.keyY.data()}, first, count,
      {box.min.x, box.min.y, box.max.x, box.max.y}, ids, keys, set);
}

} // namespace strahler::tiling
