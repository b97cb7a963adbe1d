#pragma once

#include "strahler/geometry/vec2.h"

#include <algorithm>

namespace strahler::geometry {

/// Closest point to p on segment [a, b]. Inline: it sits on the tile hot path (river curves,
/// shore distance).
inline Vec2 closestPointOnSegment(Vec2 p, Vec2 a, Vec2 b) noexcept {
  const Vec2 ab = b - a;
  const double len2 = lengthSquared(ab);
  if (len2 == 0.0)
    return a;
  const double t = std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
  return a + ab * t;
}
/// Distance from p to segment [a, b].
double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) noexcept;
/// True when segments [a, b] and [c, d] share a point (touching counts).
bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept;
/// Distance between segments [a, b] and [c, d] (0 when they intersect).
double segmentSegmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept;

} // namespace strahler::geometry
