#pragma once

#include "strahler/geometry/vec2.h"

#include <optional>
#include <string>
#include <vector>

namespace strahler::input {

/// A mountain an artist drew: a point the relief rises to.
struct MountainFeature {
  geometry::Vec2 lonLat;           ///< As drawn, degrees.
  geometry::Vec2 position;         ///< In the local frame, m.
  std::optional<double> elevation; ///< Summit height to meet (within 10 %), m; none: the law's.
  std::optional<double> radius;    ///< How far its slopes reach, m; none: chosen by scale.

  friend bool operator==(const MountainFeature&, const MountainFeature&) = default;
};

/// A ridgeline an artist drew: a continuous crest no river crosses (drawn rivers excepted).
struct RidgeFeature {
  std::vector<geometry::Vec2> lonLat; ///< As drawn, degrees; at least 2 points.
  std::vector<geometry::Vec2> line;   ///< The crest in the local frame, m.
  std::optional<double> elevation;    ///< Crest height, m; none: the relief law's.

  friend bool operator==(const RidgeFeature&, const RidgeFeature&) = default;
};

/// A main river an artist drew, from its source to its mouth on the coast or a lake shore: it
/// becomes a chain of river nodes of the network, exactly along the line.
struct RiverFeature {
  std::vector<geometry::Vec2> lonLat; ///< As drawn, degrees, source first; at least 2 points.
  std::vector<geometry::Vec2> line;   ///< The course in the local frame, m, source first.
  std::string name;                   ///< Its "name" property, "" when none.

  friend bool operator==(const RiverFeature&, const RiverFeature&) = default;
};

/// The vector map an artist drew over the coastline (`--features FILE.geojson`): GeoJSON
/// Features whose "kind" property is "mountain" (Point), "ridge" (LineString) or "river"
/// (LineString). Empty when none was given: the world is then exactly as without it.
struct Features {
  std::vector<MountainFeature> mountains; ///< In file order.
  std::vector<RidgeFeature> ridges;       ///< In file order.
  std::vector<RiverFeature> rivers;       ///< In file order.

  /// True when nothing was drawn.
  bool empty() const noexcept { return mountains.empty() && ridges.empty() && rivers.empty(); }

  friend bool operator==(const Features&, const Features&) = default;
};

} // namespace strahler::input
