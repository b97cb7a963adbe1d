#pragma once

#include "strahler/geometry/polygon_index.h"
#include "strahler/input/features.h"
#include "strahler/input/params.h"

#include <optional>
#include <vector>

namespace strahler::network {

/// A drawn river (input::RiverFeature) as the network holds it: its course with the mouth
/// snapped to the shore, and where its chain of nodes lies on it.
struct DrawnCourse {
  /// The drawn line, source first, its last point replaced by the mouth (the nearest shore
  /// point, as user mouths are snapped).
  std::vector<geometry::Vec2> line;
  std::vector<double> arc;   ///< Per point of `line`: arc length from the source, m.
  std::vector<double> chain; ///< Arc lengths of the chain's nodes, the mouth's first.
  geometry::Vec2 inward;     ///< Unit normal of the shore at the mouth, into the land.
  bool onLake = false;       ///< The mouth is on a lake shore.

  /// The point at arc length s from the source (clamped to the line).
  geometry::Vec2 at(double s) const noexcept;
  /// The point of chain node k (0: the mouth; chain.size() − 1: the source).
  geometry::Vec2 node(std::size_t k) const noexcept { return at(chain[k]); }
  /// The line between arc lengths `from` and `to` (either order), with every vertex between
  /// them, from `from` to `to`; each step at most `maxStep` metres (> 0).
  std::vector<geometry::Vec2> subPath(double from, double to, double maxStep) const;
};

/// Most distance (m) from the shore at which a drawn river's last point is taken as its mouth.
inline constexpr double kDrawnMouthMaxDistance = 5000.0;

/// The course and chain of a drawn river: the mouth is the line's last point snapped to the
/// shore of `land`; nodes follow every e (params.edgeLength) along the line from the mouth,
/// and the source (the line's first point) ends the chain. The last step is what remains,
/// shorter than e, unless that is under e/2: then the node before it is left out, and the last
/// step is between e and 1.5 e. None when no shore lies within kDrawnMouthMaxDistance of the
/// last point or the line has no length.
std::optional<DrawnCourse> drawnCourse(const input::RiverFeature& river,
                                       const geometry::PolygonIndex& land,
                                       const input::Params& params);

} // namespace strahler::network
