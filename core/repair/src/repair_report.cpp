#include "strahler/repair/coast_repair.h"

#include <array>
#include <cstdio>

namespace strahler::repair {

const char* changeKindName(ChangeKind kind) noexcept {
  switch (kind) {
  case ChangeKind::kDuplicatePoint:
    return "duplicate point";
  case ChangeKind::kSpike:
    return "spike";
  case ChangeKind::kSelfIntersection:
    return "self-intersection";
  case ChangeKind::kSelfTouch:
    return "self-touching ring";
  case ChangeKind::kOrientation:
    return "orientation";
  case ChangeKind::kDegenerateRing:
    return "ring without area";
  case ChangeKind::kOverlap:
    return "overlap";
  case ChangeKind::kPinch:
    return "pinch";
  }
  return "change";
}

std::string describe(const Change& change) {
  std::array<char, 160> head{};
  std::snprintf(head.data(), head.size(),
                "%s at (%.5f, %.5f), %.4g km²: ", changeKindName(change.kind), change.lonLat.x,
                change.lonLat.y, change.areaKm2);
  return head.data() + change.description;
}

} // namespace strahler::repair
