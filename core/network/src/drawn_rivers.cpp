#include "strahler/network/drawn_rivers.h"

#include <algorithm>
#include <cmath>

namespace strahler::network {

using geometry::Vec2;

Vec2 DrawnCourse::at(double s) const noexcept {
  if (s <= 0.0)
    return line.front();
  if (s >= arc.back())
    return line.back();
  const auto it = std::upper_bound(arc.begin(), arc.end(), s);
  const auto i = static_cast<std::size_t>(it - arc.begin()) - 1;
  const double span = arc[i + 1] - arc[i];
  return geometry::lerp(line[i], line[i + 1], span > 0.0 ? (s - arc[i]) / span : 0.0);
}

std::vector<Vec2> DrawnCourse::subPath(double from, double to, double maxStep) const {
  const double lo = std::min(from, to), hi = std::max(from, to);
  std::vector<double> stops{lo};
  for (double s : arc)
    if (s > lo && s < hi)
      stops.push_back(s);
  stops.push_back(hi);
  std::vector<Vec2> out{at(lo)};
  for (std::size_t i = 1; i < stops.size(); ++i) {
    const double span = stops[i] - stops[i - 1];
    const int steps = std::max(1, static_cast<int>(std::ceil(span / maxStep)));
    for (int k = 1; k <= steps; ++k)
      out.push_back(at(k == steps ? stops[i] : stops[i - 1] + span * k / steps));
  }
  if (from > to)
    std::reverse(out.begin(), out.end());
  return out;
}

std::optional<DrawnCourse> drawnCourse(const input::RiverFeature& river,
                                       const geometry::PolygonIndex& land,
                                       const input::Params& params) {
  if (river.line.size() < 2)
    return std::nullopt;
  const geometry::BoundaryHit hit = land.nearestBoundary(river.line.back(), kDrawnMouthMaxDistance);
  if (hit.segment < 0)
    return std::nullopt;
  const geometry::BoundarySegment& seg = land.segments()[static_cast<std::size_t>(hit.segment)];
  DrawnCourse c;
  c.line = river.line;
  c.line.back() = hit.point;
  c.inward = normalize(perpendicular(seg.b - seg.a));
  c.onLake = land.isHole(seg.ring);
  c.arc.push_back(0.0);
  for (std::size_t i = 1; i < c.line.size(); ++i)
    c.arc.push_back(c.arc.back() + distance(c.line[i - 1], c.line[i]));
  const double length = c.arc.back();
  if (!(length > 0.0))
    return std::nullopt;
  const double e = params.edgeLength;
  c.chain.push_back(length);
  for (double d = e; d < length; d += e)
    c.chain.push_back(length - d);
  // The remainder to the source is c.chain.back(); under e/2 its node is left out.
  if (c.chain.size() > 1 && c.chain.back() < 0.5 * e)
    c.chain.pop_back();
  c.chain.push_back(0.0);
  return c;
}

} // namespace strahler::network
