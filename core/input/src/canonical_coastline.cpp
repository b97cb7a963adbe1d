// One spelling of a coastline: orientation, start vertex and order of rings and polygons.
#include "strahler/input/canonical_coastline.h"

#include "json_util.h"

#include <algorithm>
#include <cmath>

namespace strahler::input {
namespace {

using geometry::Ring;
using geometry::Vec2;

bool lexicographicallyLess(Vec2 a, Vec2 b) noexcept {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

std::size_t smallestVertex(const Ring& ring) noexcept {
  std::size_t best = 0;
  for (std::size_t i = 1; i < ring.size(); ++i)
    if (lexicographicallyLess(ring[i], ring[best]))
      best = i;
  return best;
}

/// True when the ring runs counter-clockwise. At the smallest vertex the turn from the previous
/// edge to the next has the ring's orientation; the cross product there is computed from the
/// same differences in either direction, so a reversed ring gets exactly the opposite sign. It
/// is zero only for a spike there (refused by the reader); the area decides then.
bool isCounterClockwise(const Ring& ring) noexcept {
  const std::size_t n = ring.size();
  const std::size_t i = smallestVertex(ring);
  const Vec2 in = ring[i] - ring[(i + n - 1) % n];
  const Vec2 out = ring[(i + 1) % n] - ring[i];
  const double turn = in.x * out.y - in.y * out.x;
  if (turn != 0.0)
    return turn > 0.0;
  return geometry::signedArea(ring) > 0.0;
}

/// Orients the ring (counter-clockwise or not) and starts it at its smallest vertex.
void canonicalizeRing(Ring& ring, bool counterClockwise) {
  if (ring.size() < 3)
    return;
  if (isCounterClockwise(ring) != counterClockwise)
    std::reverse(ring.begin(), ring.end());
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(smallestVertex(ring)),
              ring.end());
}

/// A total order on canonical rings: by first vertex, then length, then every vertex.
bool ringLess(const Ring& a, const Ring& b) noexcept {
  if (a.empty() || b.empty() || !(a.front() == b.front()))
    return a.empty() ? !b.empty() : (!b.empty() && lexicographicallyLess(a.front(), b.front()));
  if (a.size() != b.size())
    return a.size() < b.size();
  return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(),
                                      lexicographicallyLess);
}

} // namespace

void canonicalizeCoastline(geometry::MultiPolygon& lonLat) {
  for (geometry::Polygon& polygon : lonLat) {
    canonicalizeRing(polygon.outer, true);
    for (Ring& hole : polygon.holes)
      canonicalizeRing(hole, false);
    std::sort(polygon.holes.begin(), polygon.holes.end(), ringLess);
  }
  std::sort(lonLat.begin(), lonLat.end(),
            [](const geometry::Polygon& a, const geometry::Polygon& b) {
              return ringLess(a.outer, b.outer);
            });
}

std::vector<std::string> swappedCoordinateWarnings(const geometry::MultiPolygon& lonLat) {
  std::vector<std::string> warnings;
  if (lonLat.empty())
    return warnings;
  const geometry::Aabb box = geometry::bounds(lonLat);
  const double centreLat = 0.5 * (box.min.y + box.max.y);
  if (std::abs(centreLat) <= 1.0 && box.min.x >= -90.0 && box.max.x <= 90.0)
    warnings.push_back(
        "coastline: the land lies on the equator (latitudes " + detail::formatNumber(box.min.y) +
        " to " + detail::formatNumber(box.max.y) + ", longitudes " +
        detail::formatNumber(box.min.x) + " to " + detail::formatNumber(box.max.x) +
        "); if its positions are [latitude, longitude], swap them: GeoJSON positions are "
        "[longitude, latitude]");
  return warnings;
}

} // namespace strahler::input
