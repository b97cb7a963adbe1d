#pragma once

#include "strahler/base/result.h"
#include "strahler/geometry/polygon.h"
#include "strahler/geometry/projection.h"
#include "strahler/input/features.h"
#include "strahler/input/limits.h"
#include "strahler/input/params.h"

#include <string_view>

namespace strahler::input {

/// How far the checks of drawn features let a river stray, from the grammar's edge length e.
struct FeatureTolerances {
  double offLand = 0.0; ///< A river may pass this far outside the land (0.25 e), m.
  double mouth = 0.0;   ///< A river's last point lies this near a shore at most (1.5 e), m.
};

/// The tolerances parseFeatures applies under `params`.
FeatureTolerances featureTolerances(const Params& params) noexcept;

/// Parses and validates the artist's vector map: a GeoJSON FeatureCollection (or one Feature)
/// whose features each have a "kind" property: "mountain" (Point; optional numbers
/// "elevation" and "radius", m > 0), "ridge" (LineString of ≥ 2 points; optional "elevation")
/// or "river" (LineString of ≥ 2 points from source to mouth; optional string "name"). No
/// other property is allowed (a Feature's own "id" and "bbox" members are ignored). Positions
/// are WGS84 lon/lat, projected with `projection`; `landLocal` is the land in that frame.
/// Refused, naming the feature's index, the fault and where (lon, lat): bad structure, an
/// unknown kind or property, a wrong geometry type, a non-finite or out-of-range number, two
/// equal consecutive points, more than limits.maxFeatures features or limits.maxFeatureVertices
/// points (kLimitExceeded), a mountain off the land, a river that leaves the land by more than
/// FeatureTolerances::offLand away from its mouth, a river whose last point is farther than
/// FeatureTolerances::mouth from the coast and every lake shore ("ends inland without a lake",
/// or out in the water), a river that meets (touching counts) itself, another river or a ridge
/// or turns back by more than 179°, and two river mouths closer than params.mouthSpacing (the
/// spacing of automatic mouths). Errors start with "features: ".
base::Result<Features> parseFeatures(std::string_view geoJson,
                                     const geometry::LocalProjection& projection,
                                     const geometry::MultiPolygon& landLocal, const Params& params,
                                     const InputLimits& limits = {});

} // namespace strahler::input
