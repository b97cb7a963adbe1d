#pragma once

#include "strahler/base/result.h"
#include "strahler/geometry/polygon.h"

#include <cstddef>
#include <string>
#include <vector>

namespace strahler::repair {

/// What a repair changed.
enum class ChangeKind {
  kDuplicatePoint, ///< A position repeating the one before it, removed.
  kSpike, ///< A vertex where the ring doubles back on itself (a zero-width spike), removed.
  kSelfIntersection, ///< Two segments of one ring cross: the ring is split there.
  kSelfTouch,        ///< A ring passes twice through one point: the ring is split there.
  kOrientation,      ///< A ring running the wrong way (RFC 7946), reversed.
  kDegenerateRing,   ///< A ring enclosing no area, removed.
  kOverlap,          ///< Rings or polygons that overlap, merged (union) or cut (holes).
  kPinch,            ///< Pieces of land touching at one point, joined by a tiny rhombus.
};

/// Stable lower-case name of a kind, e.g. "self-intersection".
const char* changeKindName(ChangeKind kind) noexcept;

/// One change made by `repairCoastline`, for the user's report.
struct Change {
  ChangeKind kind = ChangeKind::kDuplicatePoint;
  geometry::Vec2 lonLat;   ///< Where, in degrees.
  double areaKm2 = 0.0;    ///< Area that changed between land and water (0 for pure fixes).
  std::string description; ///< "polygon 0, ring 0: positions 511-512 and 513-514 cross ...".
};

/// One polygon as read: rings[0] the outer ring, the others holes, each without the closing
/// position but otherwise as given (duplicates, spikes, crossings, any orientation).
struct InputPolygon {
  std::string label; ///< Where it is in the input, e.g. "feature 2, polygon 0".
  std::vector<geometry::Ring> rings;
};

/// A repaired coastline and what was changed to get it.
struct RepairedCoast {
  geometry::MultiPolygon land; ///< Outer rings counter-clockwise, holes clockwise.
  std::vector<Change> changes; ///< In the order the repair made them; empty if none.
};

/// Caps on the work a repair may do.
struct RepairLimits {
  std::size_t maxCrossings = 100'000; ///< Self-intersection points over all rings.
};

/// Mends a coastline in (lon, lat) degrees so that it satisfies strahler's topology rules:
/// removes consecutive duplicate positions and zero-width spikes (Boost.Geometry's
/// remove_spikes), splits each ring where it crosses or touches itself and keeps the area it
/// encloses an odd number of times (the even-odd rule, as OGC make-valid does), subtracts the
/// union of a polygon's holes from its outer ring, unites overlapping polygons, joins pieces
/// that touch at a single point with a rhombus at most 10 m across, and orients rings as
/// RFC 7946 asks. Rings that are already valid come back unchanged (the same vertices in the
/// same order), except reversed if they ran the wrong way. Deterministic: the same input gives
/// the same output on every machine. Areas in the report use the local scale of a sphere of
/// radius 6,371 km at the piece's latitude. Errors: kInvalidInput when nothing is left, or when
/// Boost.Geometry refuses the geometry (the message says so); kLimitExceeded above `limits`.
base::Result<RepairedCoast> repairCoastline(const std::vector<InputPolygon>& polygons,
                                            const RepairLimits& limits = {});

/// The one-line text of a change: "self-intersection at (-16.4901, 63.9000), 0.0107 km²: ...".
std::string describe(const Change& change);

} // namespace strahler::repair
