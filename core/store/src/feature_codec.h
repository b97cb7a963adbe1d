#pragma once

// Private to core/store: the artist's vector map (input::Features) in the world file.

#include "strahler/base/result.h"
#include "strahler/input/features.h"
#include "strahler/v1/world.pb.h"

#include <string_view>

namespace strahler::store::detail {

/// Writes `features` into `out`, every double exactly.
void encodeFeatures(const input::Features& features, v1::Features& out);

/// Reads and validates stored features (finite numbers, lon/lat in range, elevations and radii
/// > 0, lines of ≥ 2 points with equal columns); faults are kCorrupt errors of world file `name`.
base::Result<input::Features> decodeFeatures(const v1::Features& message, std::string_view name);

} // namespace strahler::store::detail
