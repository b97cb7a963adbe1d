#include "strahler/primitives/river_primitive.h"

namespace strahler::primitives {

const char* riverTypeName(RiverType type) noexcept {
  switch (type) {
  case RiverType::kStraight:
    return "B";
  case RiverType::kSinuous:
    return "E";
  case RiverType::kBraided:
    return "D";
  case RiverType::kDelta:
    return "D-delta";
  }
  return "?";
}

geometry::Aabb supportBox(const RiverPrimitive& river) noexcept {
  geometry::Aabb box;
  for (const CurvePoint& p : river.curve)
    box.add(p.position);
  return box.expanded(river.radius);
}

} // namespace strahler::primitives
