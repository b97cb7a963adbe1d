#include "pinches.h"

#include "bg_types.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace strahler::repair::detail {
namespace {

using geometry::Vec2;

constexpr double kMetresPerDegree = 6371000.0 * 3.14159265358979323846 / 180.0;
/// Largest half-diagonal of the rhombus that joins two pieces touching at a point.
constexpr double kMaxPinchMetres = 5.0;

/// Points where the land touches itself: a vertex that appears twice among all rings.
std::vector<Vec2> findPinches(const geometry::MultiPolygon& land) {
  std::vector<std::pair<double, double>> vertices;
  for (const geometry::Polygon& polygon : land) {
    for (const Vec2 v : polygon.outer)
      vertices.emplace_back(v.x, v.y);
    for (const geometry::Ring& hole : polygon.holes)
      for (const Vec2 v : hole)
        vertices.emplace_back(v.x, v.y);
  }
  std::sort(vertices.begin(), vertices.end());
  std::vector<Vec2> pinches;
  for (std::size_t i = 1; i < vertices.size(); ++i)
    if (vertices[i] == vertices[i - 1] &&
        (pinches.empty() || !(pinches.back() == Vec2{vertices[i].first, vertices[i].second})))
      pinches.push_back({vertices[i].first, vertices[i].second});
  return pinches;
}

/// A rhombus around `at` whose half-diagonals measure at most kMaxPinchMetres and a quarter
/// of the shortest segment that ends there (so that it reaches no other vertex).
BgPolygon pinchRhombus(const geometry::MultiPolygon& land, Vec2 at) {
  const double metresPerLon = kMetresPerDegree * std::cos(at.y * 3.14159265358979323846 / 180.0);
  double radius = kMaxPinchMetres;
  const auto visit = [&](const geometry::Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (!(ring[i] == at))
        continue;
      for (const Vec2 other :
           {ring[(i + 1) % ring.size()], ring[(i + ring.size() - 1) % ring.size()]}) {
        const Vec2 d{(other.x - at.x) * metresPerLon, (other.y - at.y) * kMetresPerDegree};
        radius = std::min(radius, 0.25 * geometry::length(d));
      }
    }
  };
  for (const geometry::Polygon& polygon : land) {
    visit(polygon.outer);
    for (const geometry::Ring& hole : polygon.holes)
      visit(hole);
  }
  const double dx = radius / metresPerLon, dy = radius / kMetresPerDegree;
  BgPolygon rhombus;
  rhombus.outer() = {Point(at.x + dx, at.y), Point(at.x, at.y + dy), Point(at.x - dx, at.y),
                     Point(at.x, at.y - dy), Point(at.x + dx, at.y)};
  return rhombus;
}

} // namespace

geometry::MultiPolygon closePinches(geometry::MultiPolygon land, std::vector<Change>& changes) {
  for (int round = 0; round < 3; ++round) {
    const std::vector<Vec2> pinches = findPinches(land);
    if (pinches.empty())
      break;
    // Only the polygons with a pinch vertex are rebuilt; the others stay as they are.
    std::vector<bool> affected(land.size(), false);
    for (std::size_t p = 0; p < land.size(); ++p)
      for (const Vec2 at : pinches) {
        const auto has = [at](const geometry::Ring& ring) {
          return std::find(ring.begin(), ring.end(), at) != ring.end();
        };
        affected[p] = affected[p] || has(land[p].outer) ||
                      std::any_of(land[p].holes.begin(), land[p].holes.end(), has);
      }
    std::vector<BgPolygon> rhombusAt;
    for (const Vec2 at : pinches)
      rhombusAt.push_back(pinchRhombus(land, at));
    BgMulti pieces;
    geometry::MultiPolygon kept;
    for (std::size_t p = 0; p < land.size(); ++p) {
      if (!affected[p]) {
        kept.push_back(std::move(land[p]));
        continue;
      }
      pieces.push_back(bgPolygonOf(land[p]));
    }
    BgMulti rhombi;
    for (std::size_t k = 0; k < pinches.size(); ++k) {
      const Vec2 at = pinches[k];
      const BgPolygon& rhombus = rhombusAt[k];
      BgMulti added;
      bg::difference(rhombus, pieces, added);
      changes.push_back(
          {ChangeKind::kPinch, at, areaKm2(added),
           "the land touched itself at this point (two pieces, or a lake and the shore); a "
           "rhombus of land joins them"});
      rhombi = unite(rhombi, BgMulti{rhombus});
    }
    land = std::move(kept);
    for (geometry::Polygon& polygon : multiPolygonOf(unite(pieces, rhombi)))
      land.push_back(std::move(polygon));
  }
  return land;
}

} // namespace strahler::repair::detail
