#pragma once
// Private to core/input: user-given river mouths from GeoJSON.

#include "strahler/base/result.h"
#include "strahler/geometry/projection.h"
#include "strahler/input/limits.h"
#include "strahler/input/world_spec.h"

#include <string_view>
#include <vector>

namespace strahler::input::detail {

/// Parses mouths: a FeatureCollection of Point or MultiPoint features, one such Feature, or a
/// bare Point or MultiPoint. A feature's optional "priority" property is an integer ≥ 1
/// (default 1). Positions are projected with `projection`; more than limits.maxMouths mouths
/// is kLimitExceeded. Errors start with "mouths: " and name the feature and point.
base::Result<std::vector<UserMouth>> parseMouths(std::string_view geojson,
                                                 const geometry::LocalProjection& projection,
                                                 const InputLimits& limits);

} // namespace strahler::input::detail
