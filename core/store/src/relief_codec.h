#pragma once

// Private to core/store: the erosion's residual (construction::ReliefResidual) in the world
// file, chunk by chunk.

#include "strahler/base/result.h"
#include "strahler/construction/world_data.h"
#include "strahler/v1/world.pb.h"

#include <string_view>

namespace strahler::store::detail {

/// Largest number of residual nodes a world file may hold (2^28: 512 MiB of int16).
inline constexpr std::uint64_t kMaxReliefNodes = std::uint64_t{1} << 28;

/// Writes `relief` (not empty) into `out`: each chunk empty where all zero, else deflated.
void encodeRelief(const construction::ReliefResidual& relief, v1::Relief& out);

/// Reads and validates a stored residual (spacing, alignment, sizes, chunk count, each chunk's
/// inflated size, varints and range); faults are kCorrupt errors of world file `name`.
base::Result<construction::ReliefResidual> decodeRelief(const v1::Relief& message,
                                                        std::string_view name);

} // namespace strahler::store::detail
