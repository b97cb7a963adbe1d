#pragma once

#include "strahler/geometry/vec2.h"

namespace strahler::geometry {

/// Closest point to p on segment [a, b].
Vec2 closestPointOnSegment(Vec2 p, Vec2 a, Vec2 b) noexcept;
/// Distance from p to segment [a, b].
double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) noexcept;
/// True when segments [a, b] and [c, d] share a point (touching counts).
bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept;
/// Distance between segments [a, b] and [c, d] (0 when they intersect).
double segmentSegmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept;

} // namespace strahler::geometry
