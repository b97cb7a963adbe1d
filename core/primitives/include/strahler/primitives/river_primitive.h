#pragma once

#include "strahler/base/strong_id.h"
#include "strahler/geometry/aabb.h"
#include "strahler/geometry/vec2.h"

#include <cstdint>
#include <vector>

namespace strahler::primitives {

/// River type of a primitive: analysis::RosgenType as the world file and the evaluator keep
/// it (a stored enum with fixed values, independent of the analysis code).
enum class RiverType : std::uint8_t {
  kStraight = 0, ///< B: V-shaped valley, steep banks.
  kSinuous = 1,  ///< E: meanders, gentle banks.
  kBraided = 2,  ///< D: wide, shallow, flat.
  kDelta = 3,    ///< D at a mouth: widest and flattest.
};

/// Short name of a river type: "B", "E", "D" or "D-delta".
const char* riverTypeName(RiverType type) noexcept;

/// A point of a river curve with its water-surface elevation u_z.
struct CurvePoint {
  geometry::Vec2 position; ///< Local metres.
  double elevation = 0.0;  ///< u_z: water surface, non-increasing downstream.

  friend bool operator==(const CurvePoint&, const CurvePoint&) = default;
};

/// River primitive R (Section 6.1): a curve γ with a profile δ across it.
/// h(p) = u_z(p) + δ(d(p)), w(p) = (1 − d²/r²)², where d is the distance to γ and u_z the
/// elevation at the projection of p. Width and depth vary linearly along the curve, from
/// their upstream to their downstream value, so sections meeting at a confluence agree.
struct RiverPrimitive {
  std::vector<CurvePoint> curve; ///< Upstream first; at least 2 points.
  double widthUp = 0.0;          ///< Channel width at the upstream end, m.
  double widthDown = 0.0;        ///< Channel width at the downstream end, m.
  double depthUp = 0.0;          ///< Channel depth below the water surface, upstream, m.
  double depthDown = 0.0;        ///< ... and downstream, m.
  double radius = 0.0;           ///< r: the farthest its valley reaches (support), m.
  RiverType type = RiverType::kSinuous;
  base::NodeId node; ///< The network node at the upstream end of the section.

  friend bool operator==(const RiverPrimitive&, const RiverPrimitive&) = default;
};

/// Bounding box of a river primitive's support (curve grown by its radius).
geometry::Aabb supportBox(const RiverPrimitive& river) noexcept;

} // namespace strahler::primitives
