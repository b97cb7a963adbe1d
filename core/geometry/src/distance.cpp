#include "strahler/geometry/distance.h"

#include <algorithm>

namespace strahler::geometry {

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) noexcept {
  return distance(p, closestPointOnSegment(p, a, b));
}

namespace {
int orientation(Vec2 a, Vec2 b, Vec2 c) noexcept {
  const double v = cross(b - a, c - a);
  return (v > 0) - (v < 0);
}
bool onSegment(Vec2 a, Vec2 b, Vec2 p) noexcept {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}
} // namespace

bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept {
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4)
    return true;
  if (o1 == 0 && onSegment(a, b, c))
    return true;
  if (o2 == 0 && onSegment(a, b, d))
    return true;
  if (o3 == 0 && onSegment(c, d, a))
    return true;
  if (o4 == 0 && onSegment(c, d, b))
    return true;
  return false;
}

double segmentSegmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept {
  if (segmentsIntersect(a, b, c, d))
    return 0.0;
  return std::min({pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d),
                   pointSegmentDistance(c, a, b), pointSegmentDistance(d, a, b)});
}

} // namespace strahler::geometry
