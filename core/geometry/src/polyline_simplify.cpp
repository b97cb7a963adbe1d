#include "strahler/geometry/polyline_simplify.h"

#include "strahler/geometry/distance.h"

#include <algorithm>
#include <utility>

namespace strahler::geometry {

std::vector<std::size_t> simplifyPolyline(std::span<const Vec2> points, double tolerance) {
  const std::size_t n = points.size();
  std::vector<std::size_t> kept;
  if (n < 3) {
    for (std::size_t i = 0; i < n; ++i)
      kept.push_back(i);
    return kept;
  }
  std::vector<bool> keep(n, false);
  keep.front() = keep.back() = true;
  // Runs still to split, as (first, last) index pairs; a stack instead of recursion, as
  // river sections can hold thousands of points.
  std::vector<std::pair<std::size_t, std::size_t>> runs{{0, n - 1}};
  while (!runs.empty()) {
    const auto [first, last] = runs.back();
    runs.pop_back();
    double farthest = -1.0;
    std::size_t split = first;
    for (std::size_t i = first + 1; i < last; ++i) {
      const double d = pointSegmentDistance(points[i], points[first], points[last]);
      if (d > farthest) {
        farthest = d;
        split = i;
      }
    }
    if (split == first || farthest <= tolerance)
      continue;
    keep[split] = true;
    runs.emplace_back(first, split);
    runs.emplace_back(split, last);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i])
      kept.push_back(i);
  return kept;
}

} // namespace strahler::geometry
