#include "ring_loops.h"

#include "bg_types.h"

#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <map>
#include <utility>

namespace strahler::repair::detail {
namespace {

namespace bgi = boost::geometry::index;
using Segment = bg::model::segment<Point>;
using geometry::Vec2;

/// Intersection points closer than this (degrees, about 0.1 mm) are one point: computed
/// crossings of three segments through one place differ in their last bits.
constexpr double kMergeDistance = 1e-9;
/// Loops of less area than this (degrees², about 1e-4 m²) enclose nothing.
constexpr double kZeroArea = 1e-14;

bool near(Vec2 a, Vec2 b) noexcept {
  return std::abs(a.x - b.x) <= kMergeDistance && std::abs(a.y - b.y) <= kMergeDistance;
}

using Key = std::pair<double, double>;
Key keyOf(Vec2 v) noexcept {
  return {v.x, v.y};
}

/// Every meeting of two segments, with points next to an endpoint moved onto it.
base::Result<std::vector<Crossing>> findHits(const geometry::Ring& ring, std::size_t maxCrossings) {
  const auto m = static_cast<std::uint32_t>(ring.size());
  auto segmentAt = [&](std::uint32_t i) { return std::pair{ring[i], ring[(i + 1) % m]}; };
  std::vector<std::pair<Box, std::uint32_t>> boxes;
  boxes.reserve(m);
  for (std::uint32_t i = 0; i < m; ++i) {
    const auto [a, b] = segmentAt(i);
    boxes.emplace_back(Box(Point(std::min(a.x, b.x), std::min(a.y, b.y)),
                           Point(std::max(a.x, b.x), std::max(a.y, b.y))),
                       i);
  }
  const bgi::rtree<std::pair<Box, std::uint32_t>, bgi::rstar<16>> tree(boxes.begin(), boxes.end());
  std::vector<Crossing> hits;
  std::vector<std::pair<Box, std::uint32_t>> found;
  std::vector<Point> points;
  for (std::uint32_t i = 0; i < m; ++i) {
    found.clear();
    tree.query(bgi::intersects(boxes[i].first), std::back_inserter(found));
    std::sort(found.begin(), found.end(),
              [](const auto& x, const auto& y) { return x.second < y.second; });
    const auto [a, b] = segmentAt(i);
    for (const auto& [box, j] : found) {
      if (j <= i)
        continue;
      const auto [c, d] = segmentAt(j);
      points.clear();
      bg::intersection(Segment(toPoint(a), toPoint(b)), Segment(toPoint(c), toPoint(d)), points);
      const bool adjacent = j == i + 1 || (i == 0 && j + 1 == m);
      for (const Point& p : points) {
        Vec2 v = toVec(p);
        for (const Vec2 end : {a, b, c, d})
          if (near(v, end))
            v = end;
        // Consecutive segments meet at their shared vertex by construction.
        if (adjacent && (v == (j == i + 1 ? b : a)))
          continue;
        hits.push_back({v, i, j, v == a || v == b || v == c || v == d});
        if (hits.size() > maxCrossings)
          return base::makeError(base::ErrorCode::kLimitExceeded,
                                 "more than " + std::to_string(maxCrossings) +
                                     " self-intersections to repair (limit maxCrossings)");
      }
    }
  }
  return hits;
}

/// Merges hits at (nearly) the same point: each hit's point becomes its group's, a ring vertex
/// if the group has one (touches first), and the result holds one Crossing per group, sorted
/// by segment.
std::vector<Crossing> mergeHits(std::vector<Crossing>& hits) {
  std::stable_sort(hits.begin(), hits.end(), [](const Crossing& x, const Crossing& y) {
    return std::tie(y.touch, x.point.x, x.point.y, x.first, x.second) <
           std::tie(x.touch, y.point.x, y.point.y, y.first, y.second);
  });
  std::vector<Crossing> merged;
  std::multimap<double, std::size_t> byX;
  for (Crossing& hit : hits) {
    Crossing* same = nullptr;
    for (auto it = byX.lower_bound(hit.point.x - kMergeDistance);
         it != byX.end() && it->first <= hit.point.x + kMergeDistance; ++it)
      if (near(merged[it->second].point, hit.point)) {
        same = &merged[it->second];
        break;
      }
    if (!same) {
      byX.emplace(hit.point.x, merged.size());
      merged.push_back(hit);
      continue;
    }
    hit.point = same->point;
    same->touch = same->touch || hit.touch;
    if (std::pair{hit.first, hit.second} < std::pair{same->first, same->second}) {
      same->first = hit.first;
      same->second = hit.second;
    }
  }
  std::sort(merged.begin(), merged.end(), [](const Crossing& x, const Crossing& y) {
    return std::tie(x.first, x.second, x.point.x, x.point.y) <
           std::tie(y.first, y.second, y.point.x, y.point.y);
  });
  return merged;
}

/// The ring's vertices with every hit inserted into the two segments it lies on.
std::vector<Vec2> insertCrossings(const geometry::Ring& ring, const std::vector<Crossing>& hits) {
  const std::size_t m = ring.size();
  std::vector<std::vector<Vec2>> inserted(m);
  for (const Crossing& hit : hits)
    for (const std::uint32_t s : {hit.first, hit.second})
      if (!(hit.point == ring[s]) && !(hit.point == ring[(s + 1) % m]))
        inserted[s].push_back(hit.point);
  std::vector<Vec2> sequence;
  for (std::size_t s = 0; s < m; ++s) {
    sequence.push_back(ring[s]);
    std::vector<Vec2>& on = inserted[s];
    const Vec2 a = ring[s], direction = ring[(s + 1) % m] - a;
    std::sort(on.begin(), on.end(), [&](Vec2 x, Vec2 y) {
      return geometry::dot(x - a, direction) < geometry::dot(y - a, direction);
    });
    on.erase(std::unique(on.begin(), on.end()), on.end());
    sequence.insert(sequence.end(), on.begin(), on.end());
  }
  return sequence;
}

void addLoop(SplitRing& out, geometry::Ring vertices, int crossing) {
  // Cutting at crossings can leave a loop that runs out and back along one line (where the
  // ring itself did): such spikes enclose nothing.
  if (vertices.size() >= 3) {
    BgRing ring = toBgRing(vertices);
    bg::remove_spikes(ring);
    vertices = fromBgRing(ring);
  }
  const double area = vertices.size() < 3 ? 0.0 : geometry::signedArea(vertices);
  if (std::abs(area) < kZeroArea) {
    if (crossing >= 0) // the rest of the ring, when flat, is the whole ring: nothing to report
      out.flat.push_back({std::move(vertices), area, crossing});
    return;
  }
  out.loops.push_back({std::move(vertices), area, crossing});
}

} // namespace

base::Result<SplitRing> splitRing(const geometry::Ring& ring, std::size_t maxCrossings) {
  SplitRing out;
  STRAHLER_ASSIGN_OR_RETURN(std::vector<Crossing> hits, findHits(ring, maxCrossings));
  out.crossings = mergeHits(hits);
  if (out.crossings.empty()) {
    addLoop(out, ring, -1);
    return out;
  }
  std::map<Key, int> crossingAt;
  for (std::size_t c = 0; c < out.crossings.size(); ++c)
    crossingAt.emplace(keyOf(out.crossings[c].point), static_cast<int>(c));
  const std::vector<Vec2> sequence = insertCrossings(ring, hits);

  // Walk the ring; coming back to a point on the stack closes the loop since then.
  std::vector<Vec2> stack;
  std::map<Key, std::size_t> onStack;
  for (const Vec2 v : sequence) {
    const auto seen = onStack.find(keyOf(v));
    if (seen == onStack.end()) {
      onStack.emplace(keyOf(v), stack.size());
      stack.push_back(v);
      continue;
    }
    const std::size_t start = seen->second;
    geometry::Ring loop(stack.begin() + static_cast<std::ptrdiff_t>(start), stack.end());
    for (std::size_t k = start + 1; k < stack.size(); ++k)
      onStack.erase(keyOf(stack[k]));
    stack.resize(start + 1);
    const auto c = crossingAt.find(keyOf(v));
    addLoop(out, std::move(loop), c == crossingAt.end() ? -1 : c->second);
  }
  addLoop(out, std::move(stack), -1);
  return out;
}

} // namespace strahler::repair::detail
