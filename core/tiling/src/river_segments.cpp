#include "strahler/tiling/river_segments.h"

#include <algorithm>

namespace strahler::tiling {

using geometry::Aabb;
using geometry::Vec2;

double distance2ToSegment(Vec2 p, Vec2 a, Vec2 b) noexcept {
  const Vec2 ab = b - a;
  const double l2 = ab.x * ab.x + ab.y * ab.y;
  const double t =
      l2 > 0.0 ? std::clamp(((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / l2, 0.0, 1.0) : 0.0;
  const Vec2 d = p - (a + ab * t);
  return d.x * d.x + d.y * d.y;
}

GridRows::GridRows(const SampleGrid& grid) : grid_(grid) {
  const auto w = static_cast<std::size_t>(grid.width);
  rowY_.resize(static_cast<std::size_t>(grid.height));
  for (std::size_t j = 0; j < rowY_.size(); ++j) {
    rowY_[j] = {grid.points[j * w].y, grid.points[j * w].y};
    for (std::size_t i = 0; i < w; ++i) {
      rowY_[j].first = std::min(rowY_[j].first, grid.points[j * w + i].y);
      rowY_[j].second = std::max(rowY_[j].second, grid.points[j * w + i].y);
    }
    if (j > 0)
      southward_ = southward_ && rowY_[j].first <= rowY_[j - 1].first &&
                   rowY_[j].second <= rowY_[j - 1].second;
  }
}

std::pair<std::size_t, std::size_t> GridRows::rowsIn(const Aabb& box) const {
  if (!southward_)
    return {0, rowY_.size()};
  // Rows north of the box (least y above it) come first, rows south of it (greatest y below
  // it) last.
  const auto first = std::partition_point(rowY_.begin(), rowY_.end(),
                                          [&](const auto& row) { return row.first > box.max.y; });
  const auto end = std::partition_point(first, rowY_.end(),
                                        [&](const auto& row) { return row.second >= box.min.y; });
  return {static_cast<std::size_t>(first - rowY_.begin()),
          static_cast<std::size_t>(end - rowY_.begin())};
}

std::size_t GridRows::firstAtLeast(std::size_t j, double x) const {
  const auto w = static_cast<std::ptrdiff_t>(grid_.width);
  const auto row = grid_.points.begin() + static_cast<std::ptrdiff_t>(j) * w;
  return static_cast<std::size_t>(
      std::lower_bound(row, row + w, x, [](Vec2 p, double v) { return p.x < v; }) - row);
}

void forEachRiverSegment(const construction::World& world, const Aabb& box, double minWidth,
                         double margin, const std::function<void(const RiverSegment&)>& visit) {
  const auto& rivers = world.data().rivers;
  for (std::size_t r = 0; r < rivers.size(); ++r) {
    const primitives::RiverPrimitive& river = rivers[r];
    const Aabb support = world.riverSupport(base::PrimitiveId(static_cast<std::uint32_t>(r)));
    if (std::max(river.widthUp, river.widthDown) < minWidth ||
        !(margin > 0.0 ? support.expanded(margin) : support).intersects(box))
      continue;
    double length = 0.0;
    for (std::size_t k = 1; k < river.curve.size(); ++k)
      length += geometry::distance(river.curve[k].position, river.curve[k - 1].position);
    double travelled = 0.0;
    for (std::size_t k = 1; k < river.curve.size(); ++k) {
      const Vec2 a = river.curve[k - 1].position, b = river.curve[k].position;
      const double step = geometry::distance(a, b);
      const double t = length > 0.0 ? (travelled + 0.5 * step) / length : 0.0;
      travelled += step;
      const double half = 0.5 * (river.widthUp + t * (river.widthDown - river.widthUp));
      if (2.0 * half < minWidth)
        continue;
      Aabb segment;
      segment.add(a);
      segment.add(b);
      if (segment.expanded(half + margin).intersects(box))
        visit({a, b, half});
    }
  }
}

} // namespace strahler::tiling
