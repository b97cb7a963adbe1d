#pragma once

#include <cstddef>

namespace strahler::input {

/// Documented caps on input size; anything larger is refused with kLimitExceeded before it
/// can use much memory or time.
struct InputLimits {
  std::size_t maxFileBytes = 64u << 20;        ///< Any one input file (GeoJSON, params).
  int maxJsonDepth = 64;                       ///< Nesting depth of any JSON document.
  std::size_t maxVertices = 500'000;           ///< Coastline vertices, all rings together.
  std::size_t maxRings = 10'000;               ///< Coastline rings (islands + lakes).
  double maxAreaKm2 = 250'000.0;               ///< Land area of one world (Great Britain: 209,331).
  double maxExtentKm = 2'000.0;                ///< Largest side of the world's bounding box.
  std::size_t maxMouths = 10'000;              ///< User-given mouths.
  std::size_t maxFeatures = 10'000;            ///< Drawn features (--features), all kinds.
  std::size_t maxFeatureVertices = 200'000;    ///< Points of all drawn lines and mountains.
  std::size_t maxConstraintPixels = 64u << 20; ///< Pixels of one constraint image.
};

} // namespace strahler::input
