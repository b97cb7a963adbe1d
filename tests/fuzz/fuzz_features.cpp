// libFuzzer harness: the artist's vector map (--features GeoJSON: mountains, ridges, rivers)
// through parseFeatures, on the embedded default island.
#include "fuzz_support.h"

#include "strahler/input/coastline.h"
#include "strahler/input/feature_parser.h"
#include "strahler/input/world_spec.h"

#include <algorithm>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace strahler;
  static const input::WorldSpec island =
      input::makeWorldSpec("default", input::defaultCoastlineGeoJson(), input::Params{}).value();
  input::InputLimits limits;
  limits.maxFeatures = 64; // small caps keep each run fast; the caps themselves are checked
  limits.maxFeatureVertices = 4096;
  const auto features = input::parseFeatures(fuzz::asText(data, size), island.projection,
                                             island.land, island.params, limits);
  fuzz::requireNoInternalError(features);
  if (!features)
    return 0;
  const input::Features& f = features.value();
  fuzz::require(f.mountains.size() + f.ridges.size() + f.rivers.size() <= limits.maxFeatures,
                "at most maxFeatures features");
  for (const input::MountainFeature& m : f.mountains) {
    fuzz::require(
        std::any_of(island.land.begin(), island.land.end(),
                    [&](const geometry::Polygon& p) { return geometry::contains(p, m.position); }),
        "every mountain is on the land");
    fuzz::require(!m.elevation || *m.elevation > 0.0, "elevations are positive");
    fuzz::require(!m.radius || *m.radius > 0.0, "radii are positive");
  }
  for (const input::RidgeFeature& r : f.ridges)
    fuzz::require(r.line.size() >= 2 && r.line.size() == r.lonLat.size(),
                  "a ridge has 2 or more points in both frames");
  for (const input::RiverFeature& r : f.rivers)
    fuzz::require(r.line.size() >= 2 && r.line.size() == r.lonLat.size(),
                  "a river has 2 or more points in both frames");
  return 0;
}
