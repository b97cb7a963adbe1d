#include "land_clipper.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace strahler::blocks::detail {
namespace {

using geometry::Aabb;
using geometry::Ring;
using geometry::Vec2;

/// Segments per leaf of a ring tree.
constexpr std::size_t kLeafSize = 8;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Angle swept around c from p to q along a path that stays in an open half-plane bounded by
/// a line through c (true of any path inside a box that does not hold c).
double sweptAngle(Vec2 p, Vec2 q, Vec2 c) {
  const Vec2 u = p - c, v = q - c;
  return std::atan2(geometry::cross(u, v), geometry::dot(u, v));
}

/// Box of ring vertices first..last, both included (indices modulo the ring size).
Aabb vertexBox(const Ring& ring, std::size_t first, std::size_t last) {
  Aabb box;
  for (std::size_t i = first; i <= last; ++i)
    box.add(ring[i % ring.size()]);
  return box;
}

/// A stretch of a ring as seen from a cell's box: one segment near the box (kept) or a run of
/// segments [lo, hi) away from it, summarised by the angle it sweeps around the box centre.
struct Step {
  std::size_t lo = 0;
  std::size_t hi = 0;
  double angle = 0.0;
  bool kept = false;
};

/// Walks a ring tree, keeping the segments whose box meets `box` and merging the rest into
/// jumps, in ring order.
class StepCollector {
public:
  StepCollector(const Ring& ring, const std::vector<Aabb>& boxes, const Aabb& box)
      : ring_(ring), boxes_(boxes), box_(box), centre_(box.center()) {}

  /// The steps of the whole ring; a jump running over the ring's end is merged with the one
  /// at its start.
  std::vector<Step> collect(std::size_t leaves) {
    descend(0, 0, leaves);
    if (steps_.size() > 1 && !steps_.front().kept && !steps_.back().kept) {
      steps_.back().hi = steps_.front().hi;
      steps_.back().angle += steps_.front().angle;
      steps_.erase(steps_.begin());
    }
    return std::move(steps_);
  }

private:
  void descend(std::size_t node, std::size_t lo, std::size_t hi) {
    const std::size_t first = lo * kLeafSize, last = std::min(hi * kLeafSize, ring_.size());
    if (!boxes_[node].intersects(box_))
      return jump(first, last);
    if (hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      descend(2 * node + 1, lo, mid);
      descend(2 * node + 2, mid, hi);
      return;
    }
    for (std::size_t s = first; s < last; ++s) {
      if (vertexBox(ring_, s, s + 1).intersects(box_))
        steps_.push_back({s, s + 1, 0.0, true});
      else
        jump(s, s + 1);
    }
  }

  void jump(std::size_t lo, std::size_t hi) {
    const double angle = sweptAngle(ring_[lo], ring_[hi % ring_.size()], centre_);
    if (!steps_.empty() && !steps_.back().kept && steps_.back().hi == lo) {
      steps_.back().hi = hi;
      steps_.back().angle += angle;
    } else {
      steps_.push_back({lo, hi, angle, false});
    }
  }

  const Ring& ring_;
  const std::vector<Aabb>& boxes_;
  Aabb box_;
  Vec2 centre_;
  std::vector<Step> steps_;
};

/// Where the ray from the centre of `outer` through p meets the border of `outer`.
Vec2 projectToBorder(Vec2 p, const Aabb& outer) {
  const Vec2 c = outer.center(), h = outer.size() * 0.5, d = p - c;
  double t = std::numeric_limits<double>::infinity();
  if (d.x != 0.0)
    t = std::min(t, h.x / std::abs(d.x));
  if (d.y != 0.0)
    t = std::min(t, h.y / std::abs(d.y));
  return c + d * t;
}

/// Appends the corners of `outer` met when turning by `sweep` radians around its centre,
/// starting at angle `from` (exclusive at both ends), in the order they are met.
void appendCorners(Ring& out, double from, double sweep, const Aabb& outer) {
  const Vec2 c = outer.center(), h = outer.size() * 0.5;
  const double beta = std::atan2(h.y, h.x);
  const std::array<double, 4> angles{beta, std::numbers::pi - beta, beta - std::numbers::pi, -beta};
  const std::array<Vec2, 4> offsets{{{h.x, h.y}, {-h.x, h.y}, {-h.x, -h.y}, {h.x, -h.y}}};
  const double dir = sweep >= 0.0 ? 1.0 : -1.0;
  const double end = from + sweep;
  std::vector<std::pair<double, std::size_t>> passed;
  for (std::size_t j = 0; j < 4; ++j) {
    // The first angle of corner j strictly after `from` in the turning direction.
    double a = angles[j] + dir * kTwoPi * std::ceil(dir * (from - angles[j]) / kTwoPi);
    if (a == from)
      a += dir * kTwoPi;
    for (; dir * (end - a) > 0.0; a += dir * kTwoPi)
      passed.emplace_back(dir * a, j);
  }
  std::sort(passed.begin(), passed.end());
  for (const auto& [key, j] : passed)
    out.push_back(c + offsets[j]);
}

/// Appends a path from e to r (not included) that stays outside the box `outer` shrinks from
/// and sweeps `angle` around its centre (up to whole turns, which the endpoints fix): out
/// radially to the border of `outer`, along it, and radially back.
void appendDetour(Ring& out, Vec2 e, Vec2 r, double angle, const Aabb& outer) {
  const Vec2 c = outer.center();
  const double from = std::atan2(e.y - c.y, e.x - c.x);
  const double to = std::atan2(r.y - c.y, r.x - c.x);
  const double turns = std::nearbyint((angle - (to - from)) / kTwoPi);
  out.push_back(projectToBorder(e, outer));
  appendCorners(out, from, to - from + kTwoPi * turns, outer);
  out.push_back(projectToBorder(r, outer));
}

} // namespace

LandClipper::LandClipper(const geometry::MultiPolygon& land) {
  for (std::size_t p = 0; p < land.size(); ++p) {
    const auto polygon = static_cast<std::uint32_t>(p);
    addRing(land[p].outer, polygon, false);
    for (const Ring& hole : land[p].holes)
      addRing(hole, polygon, true);
  }
  Aabb all;
  for (const RingTree& tree : trees_)
    all.add(tree.boxes[0]);
  if (all.empty())
    all.add(Vec2{});
  const Vec2 size = all.size();
  grid_ = geometry::GridIndex(all, std::max(size.x, size.y) / 64.0);
  for (std::size_t i = 0; i < trees_.size(); ++i)
    grid_.insert(trees_[i].boxes[0], static_cast<std::uint32_t>(i));
}

void LandClipper::addRing(const Ring& ring, std::uint32_t polygon, bool hole) {
  if (ring.size() < 3)
    return;
  RingTree tree;
  tree.ring = &ring;
  tree.polygon = polygon;
  tree.hole = hole;
  tree.leaves = (ring.size() + kLeafSize - 1) / kLeafSize;
  tree.boxes.resize(4 * tree.leaves);
  buildTree(tree, 0, 0, tree.leaves);
  trees_.push_back(std::move(tree));
}

void LandClipper::buildTree(RingTree& tree, std::size_t node, std::size_t lo,
                            std::size_t hi) const {
  if (hi - lo == 1) {
    tree.boxes[node] =
        vertexBox(*tree.ring, lo * kLeafSize, std::min(hi * kLeafSize, tree.ring->size()));
    return;
  }
  const std::size_t mid = (lo + hi) / 2;
  buildTree(tree, 2 * node + 1, lo, mid);
  buildTree(tree, 2 * node + 2, mid, hi);
  tree.boxes[node] = tree.boxes[2 * node + 1];
  tree.boxes[node].add(tree.boxes[2 * node + 2]);
}

std::vector<std::uint32_t> LandClipper::ringsNear(const Aabb& box) const {
  std::vector<std::uint32_t> ids;
  grid_.query(box, [&](std::uint32_t id) {
    if (trees_[id].boxes[0].intersects(box))
      ids.push_back(id);
    return true;
  });
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

LandClipper::RingClip LandClipper::clipRing(const RingTree& tree, const Ring& cell,
                                            const Aabb& box) const {
  const Ring& ring = *tree.ring;
  const std::vector<Step> steps = StepCollector(ring, tree.boxes, box).collect(tree.leaves);
  RingClip result;
  if (steps.size() == 1 && !steps[0].kept) {
    // Nothing near the cell: the ring goes round it (whole cell) or not at all.
    result.wholeCell = std::lround(steps[0].angle / kTwoPi) != 0;
    return result;
  }
  const Vec2 size = box.size();
  const Aabb outer = box.expanded(0.5 * std::max(size.x, size.y) + 1.0);
  Ring local;
  for (const Step& step : steps) {
    local.push_back(ring[step.lo]);
    if (!step.kept)
      appendDetour(local, ring[step.lo], ring[step.hi % ring.size()], step.angle, outer);
  }
  result.ring = geometry::clipToConvex(local, cell);
  return result;
}

void LandClipper::clipPolygon(const std::uint32_t* first, const std::uint32_t* last,
                              const Ring& cell, const Aabb& box,
                              geometry::MultiPolygon& out) const {
  // A hole's box lies inside its outer ring's box, so the outer ring comes first if at all.
  if (trees_[*first].hole)
    return;
  RingClip outer = clipRing(trees_[*first], cell, box);
  geometry::Polygon piece;
  piece.outer = outer.wholeCell ? cell : std::move(outer.ring);
  if (piece.outer.empty())
    return;
  for (const std::uint32_t* id = first + 1; id != last; ++id) {
    RingClip hole = clipRing(trees_[*id], cell, box);
    if (hole.wholeCell)
      return; // the cell lies in this lake
    if (geometry::signedArea(hole.ring) != 0.0)
      piece.holes.push_back(std::move(hole.ring));
  }
  geometry::orient(piece);
  if (geometry::area(piece) > 0.0)
    out.push_back(std::move(piece));
}

geometry::MultiPolygon LandClipper::clip(const Ring& cell) const {
  geometry::MultiPolygon result;
  const Aabb box = geometry::bounds(cell);
  const std::vector<std::uint32_t> ids = ringsNear(box);
  for (std::size_t k = 0; k < ids.size();) {
    std::size_t end = k + 1;
    while (end < ids.size() && trees_[ids[end]].polygon == trees_[ids[k]].polygon)
      ++end;
    clipPolygon(ids.data() + k, ids.data() + end, cell, box, result);
    k = end;
  }
  return result;
}

} // namespace strahler::blocks::detail
