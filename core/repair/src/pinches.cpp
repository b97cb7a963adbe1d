#include "pinches.h"

#include "bg_types.h"

#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace strahler::repair::detail {
namespace {

namespace bgi = boost::geometry::index;
using Segment = bg::model::segment<Point>;
using geometry::Vec2;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMetresPerDegree = 6371000.0 * kPi / 180.0;
/// Largest half-diagonal of the rhombus that joins two pieces touching at a point.
constexpr double kMaxPinchMetres = 5.0;
/// Smallest half-diagonal: vertices nearer than this (left by rounding) do not shrink it.
constexpr double kMinPinchMetres = 0.05;
/// Contact points closer than this (degrees) are one.
constexpr double kSamePoint = 1e-9;

/// One boundary segment of the land: polygon, ring (0 outer), index within the ring.
struct Edge {
  Vec2 a, b;
  std::uint32_t polygon = 0, ring = 0, index = 0, ringSize = 0;
};

/// A place where the land touches itself, the polygons whose boundaries meet there, and the
/// distance from it to the nearest other vertex of those boundaries (metres).
struct Contact {
  Vec2 point;
  std::vector<std::uint32_t> polygons;
  double clearanceMetres = kMaxPinchMetres * 4.0;
};

double metresBetween(Vec2 p, Vec2 q) {
  const double metresPerLon = kMetresPerDegree * std::cos(p.y * kPi / 180.0);
  return geometry::length(Vec2{(q.x - p.x) * metresPerLon, (q.y - p.y) * kMetresPerDegree});
}

std::vector<Edge> edgesOf(const geometry::MultiPolygon& land) {
  std::vector<Edge> edges;
  for (std::uint32_t p = 0; p < land.size(); ++p) {
    std::uint32_t r = 0;
    const auto add = [&](const geometry::Ring& ring) {
      const auto m = static_cast<std::uint32_t>(ring.size());
      for (std::uint32_t i = 0; i < m; ++i)
        edges.push_back({ring[i], ring[(i + 1) % m], p, r, i, m});
      ++r;
    };
    add(land[p].outer);
    for (const geometry::Ring& hole : land[p].holes)
      add(hole);
  }
  return edges;
}

/// Consecutive edges of one ring, which meet at their shared vertex by construction.
bool adjacent(const Edge& s, const Edge& t) {
  if (s.polygon != t.polygon || s.ring != t.ring)
    return false;
  const std::uint32_t d = s.index > t.index ? s.index - t.index : t.index - s.index;
  return d == 1 || d + 1 == s.ringSize;
}

/// Every point where two edges meet other than consecutive edges at their shared vertex
/// (Boost.Geometry's polygons may touch themselves at points; strahler's may not).
std::vector<Contact> findContacts(const geometry::MultiPolygon& land) {
  const std::vector<Edge> edges = edgesOf(land);
  std::vector<std::pair<Box, std::uint32_t>> boxes;
  boxes.reserve(edges.size());
  for (std::uint32_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    boxes.emplace_back(Box(Point(std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y)),
                           Point(std::max(e.a.x, e.b.x), std::max(e.a.y, e.b.y))),
                       i);
  }
  const bgi::rtree<std::pair<Box, std::uint32_t>, bgi::rstar<16>> tree(boxes.begin(), boxes.end());
  std::vector<Contact> contacts;
  std::vector<std::pair<Box, std::uint32_t>> found;
  std::vector<Point> points;
  for (std::uint32_t i = 0; i < edges.size(); ++i) {
    found.clear();
    tree.query(bgi::intersects(boxes[i].first), std::back_inserter(found));
    std::sort(found.begin(), found.end(),
              [](const auto& x, const auto& y) { return x.second < y.second; });
    const Edge& s = edges[i];
    for (const auto& [box, j] : found) {
      const Edge& t = edges[j];
      if (j <= i || adjacent(s, t))
        continue;
      points.clear();
      bg::intersection(Segment(toPoint(s.a), toPoint(s.b)), Segment(toPoint(t.a), toPoint(t.b)),
                       points);
      for (const Point& p : points) {
        const Vec2 at = toVec(p);
        auto same = std::find_if(contacts.begin(), contacts.end(), [at](const Contact& c) {
          return std::abs(c.point.x - at.x) <= kSamePoint &&
                 std::abs(c.point.y - at.y) <= kSamePoint;
        });
        if (same == contacts.end())
          same = contacts.insert(contacts.end(), Contact{at, {}, kMaxPinchMetres * 4.0});
        for (const Edge* e : {&s, &t}) {
          same->polygons.push_back(e->polygon);
          for (const Vec2 end : {e->a, e->b})
            if (const double d = metresBetween(at, end); d > kMinPinchMetres)
              same->clearanceMetres = std::min(same->clearanceMetres, d);
        }
      }
    }
  }
  return contacts;
}

/// A rhombus around a contact whose half-diagonals measure a quarter of the distance to the
/// nearest other vertex there (vertices nearer than kMinPinchMetres left out), within
/// [kMinPinchMetres, kMaxPinchMetres].
BgPolygon pinchRhombus(const Contact& contact) {
  const Vec2 at = contact.point;
  const double metresPerLon = kMetresPerDegree * std::cos(at.y * kPi / 180.0);
  const double radius =
      std::clamp(0.25 * contact.clearanceMetres, kMinPinchMetres, kMaxPinchMetres);
  const double dx = radius / metresPerLon, dy = radius / kMetresPerDegree;
  BgPolygon rhombus;
  rhombus.outer() = {Point(at.x + dx, at.y), Point(at.x, at.y + dy), Point(at.x - dx, at.y),
                     Point(at.x, at.y - dy), Point(at.x + dx, at.y)};
  return rhombus;
}

/// Leaves out polygons that lie within another one's land: Boost.Geometry's union of many
/// touching pieces can return a sliver inside the land it also returns (seen on random
/// self-crossing rings); the sliver adds nothing.
geometry::MultiPolygon dropContained(geometry::MultiPolygon land) {
  std::vector<BgPolygon> polygons;
  std::vector<Box> boxes;
  for (const geometry::Polygon& polygon : land) {
    polygons.push_back(bgPolygonOf(polygon));
    boxes.push_back(bg::return_envelope<Box>(polygons.back()));
  }
  std::vector<bool> drop(land.size(), false);
  for (std::size_t i = 0; i < land.size(); ++i)
    for (std::size_t j = 0; j < land.size() && !drop[i]; ++j)
      if (i != j && !drop[j] && bg::covered_by(boxes[i], boxes[j]) &&
          bg::within(polygons[i], polygons[j]))
        drop[i] = true;
  geometry::MultiPolygon out;
  for (std::size_t i = 0; i < land.size(); ++i)
    if (!drop[i])
      out.push_back(std::move(land[i]));
  return out;
}

} // namespace

geometry::MultiPolygon closePinches(geometry::MultiPolygon land, std::vector<Change>& changes) {
  for (int round = 0; round < 3; ++round) {
    const std::vector<Contact> contacts = findContacts(land);
    if (contacts.empty())
      break;
    // Only the polygons with a contact are rebuilt; the others stay as they are.
    std::vector<bool> affected(land.size(), false);
    for (const Contact& contact : contacts)
      for (const std::uint32_t p : contact.polygons)
        affected[p] = true;
    BgMulti pieces;
    geometry::MultiPolygon kept;
    for (std::size_t p = 0; p < land.size(); ++p) {
      if (affected[p])
        pieces.push_back(bgPolygonOf(land[p]));
      else
        kept.push_back(std::move(land[p]));
    }
    BgMulti rhombi;
    for (const Contact& contact : contacts) {
      const BgPolygon rhombus = pinchRhombus(contact);
      BgMulti added;
      bg::difference(rhombus, pieces, added);
      changes.push_back({ChangeKind::kPinch, contact.point, areaKm2(added),
                         "the land touched itself at this point (two pieces, or a lake and the "
                         "shore); a rhombus of land joins them"});
      rhombi = unite(rhombi, BgMulti{rhombus});
    }
    land = std::move(kept);
    for (geometry::Polygon& polygon : multiPolygonOf(unite(pieces, rhombi)))
      land.push_back(std::move(polygon));
    land = dropContained(std::move(land));
  }
  return land;
}

} // namespace strahler::repair::detail
