#pragma once

#include "strahler/geometry/vec2.h"

#include <algorithm>
#include <limits>

namespace strahler::geometry {

/// Axis-aligned box; empty() until a point is added.
struct Aabb {
  Vec2 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  /// True when no point has been added.
  constexpr bool empty() const noexcept { return min.x > max.x || min.y > max.y; }
  /// Grows the box to hold p.
  constexpr void add(Vec2 p) noexcept {
    min = {std::min(min.x, p.x), std::min(min.y, p.y)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y)};
  }
  /// Grows the box to hold b.
  constexpr void add(const Aabb& b) noexcept {
    if (b.empty())
      return;
    add(b.min);
    add(b.max);
  }
  /// The box grown by r on every side.
  constexpr Aabb expanded(double r) const noexcept {
    return {{min.x - r, min.y - r}, {max.x + r, max.y + r}};
  }
  /// Width and height.
  constexpr Vec2 size() const noexcept { return max - min; }
  /// Centre point.
  constexpr Vec2 center() const noexcept { return (min + max) * 0.5; }
  /// True when p is inside or on the border.
  constexpr bool contains(Vec2 p) const noexcept {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y;
  }
  /// True when the two boxes share at least one point.
  constexpr bool intersects(const Aabb& b) const noexcept {
    return min.x <= b.max.x && b.min.x <= max.x && min.y <= b.max.y && b.min.y <= max.y;
  }
};

} // namespace strahler::geometry
