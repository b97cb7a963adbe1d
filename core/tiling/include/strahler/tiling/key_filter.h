#pragma once

#include "strahler/construction/world.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace strahler::tiling {

/// Entries that keepKeysWithin() may write past the last id it keeps.
inline constexpr std::size_t kKeyFilterOverrun = 16;

/// Copies, in order, each ids[k] whose keys[k] lies in [low, high] to `out` and returns how
/// many it kept. `out` must have room for keys.size() + kKeyFilterOverrun ids (vector stores
/// write whole vectors past the last kept id). Runs with vector instructions of `set` where it
/// has a kernel for them (AVX2, AVX-512), else scalar code without a branch per key; every set
/// keeps the same ids.
std::size_t keepKeysWithin(std::span<const float> keys, const std::uint32_t* ids, float low,
                           float high, std::uint32_t* out,
                           construction::InstructionSet set = construction::instructionSet());

} // namespace strahler::tiling
