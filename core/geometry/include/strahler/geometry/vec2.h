#pragma once

#include <cmath>

namespace strahler::geometry {

/// A 2D point or vector in metres (local frame) or degrees (lon, lat), by context.
struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2 operator+(Vec2 o) const noexcept { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(Vec2 o) const noexcept { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator*(double s) const noexcept { return {x * s, y * s}; }
  constexpr Vec2 operator/(double s) const noexcept { return {x / s, y / s}; }
  constexpr Vec2& operator+=(Vec2 o) noexcept { return *this = *this + o; }
  constexpr Vec2& operator-=(Vec2 o) noexcept { return *this = *this - o; }
  constexpr bool operator==(const Vec2&) const noexcept = default;
};

/// Dot product.
constexpr double dot(Vec2 a, Vec2 b) noexcept {
  return a.x * b.x + a.y * b.y;
}
/// z of the 3D cross product (positive when b is counter-clockwise from a).
constexpr double cross(Vec2 a, Vec2 b) noexcept {
  return a.x * b.y - a.y * b.x;
}
/// Squared length.
constexpr double lengthSquared(Vec2 a) noexcept {
  return dot(a, a);
}
/// Euclidean length.
inline double length(Vec2 a) noexcept {
  return std::sqrt(dot(a, a));
}
/// Euclidean distance.
inline double distance(Vec2 a, Vec2 b) noexcept {
  return length(a - b);
}
/// Unit vector along a (a must not be zero).
inline Vec2 normalize(Vec2 a) noexcept {
  return a / length(a);
}
/// a rotated by +90 degrees.
constexpr Vec2 perpendicular(Vec2 a) noexcept {
  return {-a.y, a.x};
}
/// Unit vector at `angle` radians from the x axis.
inline Vec2 direction(double angle) noexcept {
  return {std::cos(angle), std::sin(angle)};
}
/// Linear interpolation a + t (b - a).
constexpr Vec2 lerp(Vec2 a, Vec2 b, double t) noexcept {
  return a + (b - a) * t;
}

} // namespace strahler::geometry
