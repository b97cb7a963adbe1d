#pragma once
// Private to core/input: the geometric checks of drawn features (land, mouths, crossings).

#include "strahler/base/result.h"
#include "strahler/geometry/polygon.h"
#include "strahler/geometry/projection.h"
#include "strahler/input/feature_parser.h"

#include <cstddef>
#include <string>
#include <vector>

namespace strahler::input::detail {

/// Where each parsed feature came from: its index in the file and a short label
/// ("feature 3 (river \"Golo\")"), per kind, in the order of Features' vectors.
struct FeatureLabels {
  std::vector<std::string> mountains;
  std::vector<std::string> ridges;
  std::vector<std::string> rivers;
};

/// Checks parsed features against the land and each other (parseFeatures's geometric rules);
/// the first fault found, in file order within each rule, is the error.
base::Status checkFeatures(const Features& features, const FeatureLabels& labels,
                           const geometry::LocalProjection& projection,
                           const geometry::MultiPolygon& landLocal, const Params& params);

/// "(9.12345, 42.12345)": a lon/lat to 5 decimals (about a metre), for messages.
std::string lonLatText(geometry::Vec2 lonLat);

} // namespace strahler::input::detail
