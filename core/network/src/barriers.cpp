#include "barriers.h"

#include "strahler/geometry/distance.h"

#include <algorithm>
#include <cmath>

namespace strahler::network::detail {

using geometry::Vec2;

Barriers::Barriers(const input::WorldSpec& spec, const geometry::PolygonIndex& land,
                   const std::vector<std::optional<DrawnCourse>>& courses)
    : sigma_(spec.params.sigma), ridgeClearance_(spec.params.delta) {
  if (spec.features.ridges.empty() && courses.empty())
    return;
  geometry::Aabb box = land.bounds();
  for (const input::RidgeFeature& r : spec.features.ridges)
    for (Vec2 p : r.line)
      box.add(p);
  grid_ = geometry::GridIndex(box.expanded(sigma_), std::max(sigma_, ridgeClearance_));
  // Long drawn segments are cut into pieces of at most σ, so that queries stay local.
  const auto addLine = [&](const std::vector<Vec2>& line, int river) {
    double s = 0.0;
    for (std::size_t i = 1; i < line.size(); ++i) {
      const double length = distance(line[i - 1], line[i]);
      const int steps = std::max(1, static_cast<int>(std::ceil(length / sigma_)));
      for (int k = 0; k < steps; ++k) {
        const double t0 = double(k) / steps, t1 = double(k + 1) / steps;
        add({geometry::lerp(line[i - 1], line[i], t0), geometry::lerp(line[i - 1], line[i], t1),
             s + t0 * length, s + t1 * length, river});
      }
      s += length;
    }
  };
  for (const input::RidgeFeature& r : spec.features.ridges)
    addLine(r.line, -1);
  for (std::size_t i = 0; i < courses.size(); ++i)
    if (courses[i])
      addLine(courses[i]->line, static_cast<int>(i));
}

void Barriers::add(const Piece& piece) {
  geometry::Aabb box;
  box.add(piece.a);
  box.add(piece.b);
  grid_.insert(box, static_cast<std::uint32_t>(pieces_.size()));
  pieces_.push_back(piece);
}

bool Barriers::allows(Vec2 from, Vec2 to, const ChainPlace& at) const {
  if (pieces_.empty())
    return true;
  geometry::Aabb box;
  box.add(from);
  box.add(to);
  // The part of the edge away from its first node: a tributary leaves the drawn river there.
  const Vec2 away = geometry::lerp(from, to, 0.1);
  return grid_.query(box.expanded(std::max(sigma_, ridgeClearance_)), [&](std::uint32_t i) {
    const Piece& q = pieces_[i];
    if (q.river < 0)
      return geometry::segmentSegmentDistance(from, to, q.a, q.b) > ridgeClearance_;
    if (q.river == at.river && q.s1 >= at.lo && q.s0 <= at.hi)
      return geometry::segmentSegmentDistance(away, to, q.a, q.b) > 0.0;
    return geometry::segmentSegmentDistance(from, to, q.a, q.b) > sigma_;
  });
}

bool Barriers::farFromRivers(Vec2 p) const {
  geometry::Aabb box;
  box.add(p);
  return grid_.query(box.expanded(sigma_), [&](std::uint32_t i) {
    const Piece& q = pieces_[i];
    return q.river < 0 || geometry::pointSegmentDistance(p, q.a, q.b) > sigma_;
  });
}

} // namespace strahler::network::detail
