// The repair's steps, in order: duplicates and spikes, self-intersections (even-odd rule),
// holes, overlapping polygons, pinches. Each reports what it changed.
#include "strahler/repair/coast_repair.h"

#include "bg_types.h"
#include "pinches.h"
#include "ring_loops.h"

#include "strahler/base/guarded.h"

#include <algorithm>
#include <exception>
#include <map>
#include <new>
#include <optional>
#include <utility>

namespace strahler::repair {
namespace {

using base::ErrorCode;
using base::makeError;
using detail::BgMulti;
using detail::BgPolygon;
using detail::Point;
using detail::unite;
using geometry::Vec2;
namespace bg = boost::geometry;

std::string ringName(const std::string& label, std::size_t ring) {
  return label + ", ring " + std::to_string(ring);
}

/// "positions 511-512": segment k of a ring whose vertex k came from input position
/// positions[k]; the last segment ends at the closing position.
std::string segmentName(const std::vector<std::uint32_t>& positions, std::uint32_t k,
                        std::uint32_t closing) {
  const std::uint32_t to = k + 1 < positions.size() ? positions[k + 1] : closing;
  return "positions " + std::to_string(positions[k]) + "-" + std::to_string(to);
}

/// A ring without duplicates and spikes, and the input position of each vertex.
struct CleanRing {
  geometry::Ring vertices;
  std::vector<std::uint32_t> positions;
  std::uint32_t closing = 0; ///< Input position of the closing repeat.
};

/// Removes repeated positions and spikes with Boost.Geometry's remove_spikes and reports
/// each vertex it removed (found by matching the output against the input in order).
CleanRing removeSpikes(const geometry::Ring& raw, const std::string& where,
                       std::vector<Change>& changes) {
  CleanRing out;
  out.closing = static_cast<std::uint32_t>(raw.size());
  detail::BgRing ring = detail::toBgRing(raw);
  bg::remove_spikes(ring);
  out.vertices = detail::fromBgRing(ring);
  const std::size_t m = raw.size();
  std::vector<bool> kept(m, false);
  std::size_t j = 0;
  for (std::size_t i = 0; i < m && j < out.vertices.size(); ++i)
    if (raw[i] == out.vertices[j]) {
      kept[i] = true;
      out.positions.push_back(static_cast<std::uint32_t>(i));
      ++j;
    }
  if (j < out.vertices.size()) { // cannot happen for a subsequence; keep the report honest
    out.positions.resize(out.vertices.size());
    for (std::size_t k = 0; k < out.positions.size(); ++k)
      out.positions[k] = static_cast<std::uint32_t>(k);
    changes.push_back({ChangeKind::kSpike, raw.empty() ? Vec2{} : raw[0], 0.0,
                       where + ": " + std::to_string(m - out.vertices.size()) +
                           " positions removed (duplicates or spikes)"});
    return out;
  }
  for (std::size_t i = 0; i < m; ++i) {
    if (kept[i])
      continue;
    const std::size_t before = (i + m - 1) % m, after = (i + 1) % m;
    if (raw[i] == raw[before] || raw[i] == raw[after]) {
      const std::size_t same = raw[i] == raw[before] ? before : after;
      changes.push_back({ChangeKind::kDuplicatePoint, raw[i], 0.0,
                         where + ": position " + std::to_string(i) + " repeats position " +
                             std::to_string(same) + "; removed"});
      continue;
    }
    // The spike's triangle with its nearest kept neighbours: no area for an exact spike.
    std::size_t p = before, n = after;
    while (!kept[p] && p != i)
      p = (p + m - 1) % m;
    while (!kept[n] && n != i)
      n = (n + 1) % m;
    detail::BgRing triangle{detail::toPoint(raw[p]), detail::toPoint(raw[i]),
                            detail::toPoint(raw[n]), detail::toPoint(raw[p])};
    changes.push_back({ChangeKind::kSpike, raw[i], detail::areaKm2(triangle),
                       where + ": the ring turns back on itself at position " + std::to_string(i) +
                           " (a spike); its tip removed"});
  }
  return out;
}

/// Reverses a ring in place, keeping its first vertex first.
void reverseRing(geometry::Ring& ring) {
  if (ring.size() > 1)
    std::reverse(ring.begin() + 1, ring.end());
}

/// One ring after the ring-level repairs: either unchanged (`simple`, oriented for its role),
/// or the area it encloses by the even-odd rule.
struct RingResult {
  bool empty = false;
  bool simple = true;
  geometry::Ring ring;
  BgMulti area; ///< Always set (for the simple case too: the ring as a polygon).
};

/// The area a loop encloses by the even-odd rule. A loop is simple by construction, but where
/// merged or rounded crossing points leave it touching itself it is split again (a few levels
/// at most); Boost.Geometry's validity check decides.
BgMulti evenOddArea(const geometry::Ring& loop, const std::string& where,
                    const RepairLimits& limits, int depth = 0) {
  const BgPolygon polygon = detail::polygonOf(loop);
  std::string reason;
  if (bg::is_valid(polygon, reason))
    return {polygon};
  auto split = detail::splitRing(loop, limits.maxCrossings);
  if (depth >= 3 || !split.ok() || split.value().crossings.empty())
    throw std::runtime_error(where + ": a piece is not valid after splitting (" + reason + ")");
  BgMulti area;
  for (const detail::Loop& piece : split.value().loops) {
    BgMulti next;
    bg::sym_difference(area, evenOddArea(piece.vertices, where, limits, depth + 1), next);
    area = std::move(next);
  }
  return area;
}

/// Repairs one ring on its own: spikes, duplicates, orientation, self-intersections.
base::Result<RingResult> repairRing(const geometry::Ring& raw, bool outer, const std::string& where,
                                    const RepairLimits& limits, std::vector<Change>& changes) {
  RingResult out;
  const CleanRing clean = removeSpikes(raw, where, changes);
  auto split = clean.vertices.size() >= 3 ? detail::splitRing(clean.vertices, limits.maxCrossings)
                                          : base::Result<detail::SplitRing>(detail::SplitRing{});
  if (!split.ok()) {
    base::Error error = std::move(split).error();
    error.message = where + ": " + error.message;
    return error;
  }
  const detail::SplitRing& pieces = split.value();
  if (pieces.loops.empty()) {
    changes.push_back({ChangeKind::kDegenerateRing, raw.empty() ? Vec2{} : raw[0], 0.0,
                       where + ": the ring encloses no area; removed"});
    out.empty = true;
    return out;
  }
  for (const detail::Loop& flat : pieces.flat) {
    const detail::Crossing& c = pieces.crossings[static_cast<std::size_t>(flat.crossing)];
    changes.push_back({ChangeKind::kSpike, c.point, 0.0,
                       where + ": segments at " +
                           segmentName(clean.positions, c.first, clean.closing) + " and " +
                           segmentName(clean.positions, c.second, clean.closing) +
                           " run along each other; the zero-width loop of " +
                           std::to_string(flat.vertices.size()) + " vertices there removed"});
  }
  std::size_t main = 0;
  for (std::size_t k = 1; k < pieces.loops.size(); ++k)
    if (std::abs(pieces.loops[k].signedArea) > std::abs(pieces.loops[main].signedArea))
      main = k;
  const bool counterClockwise = pieces.loops[main].signedArea > 0.0;
  if (counterClockwise != outer)
    changes.push_back(
        {ChangeKind::kOrientation, clean.vertices[0], 0.0,
         where + ": the ring runs " +
             (outer ? "clockwise; reversed (RFC 7946: outer rings run "
                      "counter-clockwise)"
                    : "counter-clockwise; reversed (RFC 7946: holes run clockwise)")});
  out.area.push_back(detail::polygonOf(pieces.loops[main].vertices));
  if (pieces.crossings.empty()) {
    out.ring = pieces.loops[main].vertices;
    if (counterClockwise != outer)
      reverseRing(out.ring);
    return out;
  }
  // The even-odd rule: a point is inside when an odd number of loops enclose it.
  out.simple = false;
  out.area = evenOddArea(pieces.loops[main].vertices, where, limits);
  for (std::size_t k = 0; k < pieces.loops.size(); ++k) {
    if (k == main)
      continue;
    BgMulti next;
    bg::sym_difference(out.area, evenOddArea(pieces.loops[k].vertices, where, limits), next);
    out.area = std::move(next);
  }
  for (std::size_t k = 0; k < pieces.loops.size(); ++k) {
    if (k == main)
      continue;
    const detail::Loop& loop = pieces.loops[k];
    const BgPolygon piece = detail::polygonOf(loop.vertices);
    Point inside;
    bg::point_on_surface(piece, inside);
    const bool land = bg::within(inside, out.area) == outer;
    std::string what;
    Vec2 at = loop.vertices.front();
    ChangeKind kind = ChangeKind::kSelfIntersection;
    // The rest of the ring (no crossing of its own) was split from the main loop where the
    // main loop was cut off.
    const int crossing = loop.crossing >= 0 ? loop.crossing : pieces.loops[main].crossing;
    if (crossing >= 0) {
      const detail::Crossing& c = pieces.crossings[static_cast<std::size_t>(crossing)];
      at = c.point;
      kind = c.touch ? ChangeKind::kSelfTouch : ChangeKind::kSelfIntersection;
      what = "segments at " + segmentName(clean.positions, c.first, clean.closing) + " and " +
             segmentName(clean.positions, c.second, clean.closing) +
             (c.touch ? " touch" : " cross") + "; ";
    }
    changes.push_back({kind, at, detail::areaKm2(piece),
                       where + ": " + what + "the ring was split there and a loop of " +
                           std::to_string(loop.vertices.size()) + " vertices " +
                           (land ? "kept as land" : "left as water")});
  }
  return out;
}

/// The polygon's land after its rings were repaired: the outer ring's area minus its holes'.
struct PolygonResult {
  bool simple = true;                ///< `rings` can be used as they are.
  std::vector<geometry::Ring> rings; ///< When simple: the outer ring, then the holes.
  BgMulti area;                      ///< Always set.
};

/// Where a report about a piece should point: its centroid, or `fallback` when it is empty.
Vec2 placeOf(const BgMulti& piece, Vec2 fallback) {
  if (bg::is_empty(piece))
    return fallback;
  Point c;
  bg::centroid(piece, c);
  return detail::toVec(c);
}

/// The rings of every polygon of `area` as closed linestrings.
std::vector<detail::BgLine> boundaries(const BgMulti& area) {
  std::vector<detail::BgLine> lines;
  for (const BgPolygon& polygon : area) {
    lines.emplace_back(polygon.outer().begin(), polygon.outer().end());
    for (const auto& hole : polygon.inners())
      lines.emplace_back(hole.begin(), hole.end());
  }
  return lines;
}

/// A point where the boundaries of `a` and `b` meet, if they do.
std::optional<Vec2> contactPoint(const BgMulti& a, const BgMulti& b) {
  for (const detail::BgLine& x : boundaries(a))
    for (const detail::BgLine& y : boundaries(b)) {
      std::vector<Point> points;
      bg::intersection(x, y, points);
      if (!points.empty())
        return detail::toVec(points.front());
    }
  return std::nullopt;
}

/// True when `inner` lies inside `outer` without touching its boundary.
bool strictlyInside(const BgMulti& inner, const BgMulti& outer) {
  return bg::within(inner, outer) && !contactPoint(inner, outer);
}

base::Result<std::optional<PolygonResult>>
repairPolygon(const InputPolygon& input, const RepairLimits& limits, std::vector<Change>& changes) {
  std::vector<RingResult> rings;
  std::vector<std::size_t> holes;
  for (std::size_t r = 0; r < input.rings.size(); ++r) {
    STRAHLER_ASSIGN_OR_RETURN(
        RingResult ring,
        repairRing(input.rings[r], r == 0, ringName(input.label, r), limits, changes));
    if (r == 0 && ring.empty)
      return std::optional<PolygonResult>{}; // no land: its holes go with it
    if (r > 0 && !ring.empty)
      holes.push_back(r);
    rings.push_back(std::move(ring));
  }
  PolygonResult out;
  out.simple = rings[0].simple;
  // A hole must lie strictly inside the outer ring and apart from the other holes.
  for (std::size_t a = 0; a < holes.size(); ++a) {
    const RingResult& hole = rings[holes[a]];
    out.simple = out.simple && hole.simple;
    if (!strictlyInside(hole.area, rings[0].area)) {
      out.simple = false;
      BgMulti outside;
      bg::difference(hole.area, rings[0].area, outside);
      const Vec2 fallback = contactPoint(hole.area, rings[0].area)
                                .value_or(detail::toVec(hole.area.front().outer().front()));
      changes.push_back({ChangeKind::kOverlap, placeOf(outside, fallback), detail::areaKm2(outside),
                         ringName(input.label, holes[a]) +
                             ": the hole reaches outside its outer ring or touches it; only its "
                             "part inside the land is water"});
    }
    for (std::size_t b = a + 1; b < holes.size(); ++b)
      if (bg::intersects(bg::return_envelope<detail::Box>(hole.area),
                         bg::return_envelope<detail::Box>(rings[holes[b]].area)) &&
          bg::intersects(hole.area, rings[holes[b]].area)) {
        out.simple = false;
        BgMulti common;
        bg::intersection(hole.area, rings[holes[b]].area, common);
        const Vec2 fallback = contactPoint(hole.area, rings[holes[b]].area).value_or(Vec2{});
        changes.push_back({ChangeKind::kOverlap, placeOf(common, fallback), detail::areaKm2(common),
                           input.label + ": holes (rings " + std::to_string(holes[a]) + " and " +
                               std::to_string(holes[b]) + ") overlap or touch; merged"});
      }
  }
  if (out.simple) {
    out.rings.push_back(rings[0].ring);
    BgPolygon polygon = rings[0].area.front();
    for (const std::size_t h : holes) {
      out.rings.push_back(rings[h].ring);
      polygon.inners().push_back(rings[h].area.front().outer());
      std::reverse(polygon.inners().back().begin(), polygon.inners().back().end());
    }
    out.area = {std::move(polygon)};
    return std::optional<PolygonResult>(std::move(out));
  }
  BgMulti water;
  for (const std::size_t h : holes)
    water = unite(water, rings[h].area);
  bg::difference(rings[0].area, water, out.area);
  return std::optional<PolygonResult>(std::move(out));
}

/// Unites polygons that overlap or touch; the others stay as they are.
void mergeOverlaps(std::vector<PolygonResult>& polygons, const std::vector<std::string>& labels,
                   std::vector<Change>& changes) {
  const std::size_t n = polygons.size();
  std::vector<detail::Box> boxes;
  for (const PolygonResult& p : polygons)
    boxes.push_back(bg::return_envelope<detail::Box>(p.area));
  std::vector<std::size_t> group(n);
  for (std::size_t i = 0; i < n; ++i)
    group[i] = i;
  auto root = [&](std::size_t i) {
    while (group[i] != i)
      i = group[i] = group[group[i]];
    return i;
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!bg::intersects(boxes[i], boxes[j]) ||
          !bg::intersects(polygons[i].area, polygons[j].area))
        continue;
      BgMulti common;
      bg::intersection(polygons[i].area, polygons[j].area, common);
      const Vec2 fallback = contactPoint(polygons[i].area, polygons[j].area).value_or(Vec2{});
      changes.push_back({ChangeKind::kOverlap, placeOf(common, fallback), detail::areaKm2(common),
                         labels[i] + " and " + labels[j] + " overlap or touch; united"});
      const std::size_t a = root(i), b = root(j);
      group[std::max(a, b)] = std::min(a, b);
    }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = root(i);
    if (r == i)
      continue;
    polygons[r].area = unite(polygons[r].area, polygons[i].area);
    polygons[r].simple = false;
    polygons[i].area.clear();
    polygons[i].rings.clear();
    polygons[i].simple = false;
  }
}

/// The final polygons: simple ones as they came, the others as Boost.Geometry built them.
geometry::MultiPolygon collect(const std::vector<PolygonResult>& polygons) {
  geometry::MultiPolygon land;
  for (const PolygonResult& p : polygons) {
    if (p.simple) {
      land.push_back(geometry::Polygon{p.rings[0], {p.rings.begin() + 1, p.rings.end()}});
      continue;
    }
    for (geometry::Polygon& polygon : detail::multiPolygonOf(p.area))
      land.push_back(std::move(polygon));
  }
  return land;
}

base::Result<RepairedCoast> repairUnguarded(const std::vector<InputPolygon>& input,
                                            const RepairLimits& limits) {
  RepairedCoast out;
  std::vector<PolygonResult> polygons;
  std::vector<std::string> labels;
  for (const InputPolygon& polygon : input) {
    if (polygon.rings.empty())
      continue;
    STRAHLER_ASSIGN_OR_RETURN(std::optional<PolygonResult> repaired,
                              repairPolygon(polygon, limits, out.changes));
    if (repaired) {
      polygons.push_back(std::move(*repaired));
      labels.push_back(polygon.label);
    }
  }
  mergeOverlaps(polygons, labels, out.changes);
  out.land = detail::closePinches(collect(polygons), out.changes);
  if (out.land.empty())
    return makeError(ErrorCode::kInvalidInput,
                     "coastline: nothing is left after the repair: every ring encloses no area");
  return out;
}

} // namespace

base::Result<RepairedCoast> repairCoastline(const std::vector<InputPolygon>& polygons,
                                            const RepairLimits& limits) {
  return base::guarded({.label = "coastline",
                        .outOfMemory = "out of memory while repairing",
                        .failure = ErrorCode::kInvalidInput,
                        .failurePrefix = "the repair could not mend this coastline: "},
                       [&] { return repairUnguarded(polygons, limits); });
}

} // namespace strahler::repair
