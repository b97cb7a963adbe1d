#include "strahler/render/contours.h"

#include "strahler/base/assert.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

namespace strahler::render {
namespace {

/// A grid edge: 2·(row · width + column) for the edge east of a sample, +1 for the one south.
using EdgeId = std::int64_t;

struct Segment {
  EdgeId a = 0, b = 0;
};

/// The heights and the crossing points of their grid edges.
class Grid {
public:
  Grid(std::span<const double> heights, int width) : h_(heights), w_(width) {}

  double at(int i, int j) const {
    return h_[static_cast<std::size_t>(j) * static_cast<std::size_t>(w_) +
              static_cast<std::size_t>(i)];
  }
  EdgeId east(int i, int j) const { return 2 * (static_cast<EdgeId>(j) * w_ + i); }
  EdgeId south(int i, int j) const { return east(i, j) + 1; }

  /// The crossing point of `edge` at `level`, in grid coordinates.
  geometry::Vec2 point(EdgeId edge, double level) const {
    const EdgeId cell = edge / 2;
    const int i = static_cast<int>(cell % w_), j = static_cast<int>(cell / w_);
    const bool horizontal = edge % 2 == 0;
    const double h0 = at(i, j), h1 = horizontal ? at(i + 1, j) : at(i, j + 1);
    const double t = (level - h0) / (h1 - h0);
    return horizontal ? geometry::Vec2{i + t, static_cast<double>(j)}
                      : geometry::Vec2{static_cast<double>(i), j + t};
  }

private:
  std::span<const double> h_;
  int w_ = 0;
};

/// The segments of cell (i, j) at `level` (marching squares; saddles by the cell's mean).
void cellSegments(const Grid& g, int i, int j, double level, std::vector<Segment>& out) {
  // Corners north-west (1), north-east (2), south-east (4), south-west (8); at or above: set.
  const double nw = g.at(i, j), ne = g.at(i + 1, j), se = g.at(i + 1, j + 1), sw = g.at(i, j + 1);
  const int mask =
      (nw >= level ? 1 : 0) | (ne >= level ? 2 : 0) | (se >= level ? 4 : 0) | (sw >= level ? 8 : 0);
  const EdgeId n = g.east(i, j), e = g.south(i + 1, j), s = g.east(i, j + 1), w = g.south(i, j);
  switch (mask) {
  case 1:
  case 14:
    out.push_back({w, n});
    break;
  case 2:
  case 13:
    out.push_back({n, e});
    break;
  case 3:
  case 12:
    out.push_back({w, e});
    break;
  case 4:
  case 11:
    out.push_back({e, s});
    break;
  case 6:
  case 9:
    out.push_back({n, s});
    break;
  case 7:
  case 8:
    out.push_back({w, s});
    break;
  case 5:
  case 10:
    // Corners north-west and south-east on one side: joined through the centre when the mean
    // is on their side too.
    if ((mask == 5) == (0.25 * (nw + ne + se + sw) >= level)) {
      out.push_back({w, s});
      out.push_back({n, e});
    } else {
      out.push_back({w, n});
      out.push_back({e, s});
    }
    break;
  default:
    break;
  }
}

/// The (at most two) segments that end on each grid edge, for one level at a time: a table
/// over every edge, reset after each level where it was written.
class EdgeEnds {
public:
  explicit EdgeEnds(std::size_t edges) : ends_(edges, {kNone, kNone}) {}

  void fill(const std::vector<Segment>& segments) {
    for (std::size_t s = 0; s < segments.size(); ++s)
      for (const EdgeId e : {segments[s].a, segments[s].b}) {
        auto& slot = ends_[static_cast<std::size_t>(e)];
        (slot[0] == kNone ? slot[0] : slot[1]) = static_cast<std::uint32_t>(s);
      }
  }
  void clear(const std::vector<Segment>& segments) {
    for (const Segment& s : segments)
      ends_[static_cast<std::size_t>(s.a)] = ends_[static_cast<std::size_t>(s.b)] = {kNone, kNone};
  }
  int degree(EdgeId e) const {
    const auto& slot = ends_[static_cast<std::size_t>(e)];
    return (slot[0] != kNone ? 1 : 0) + (slot[1] != kNone ? 1 : 0);
  }
  /// The segment on `e` other than those already used, or kNone.
  std::uint32_t unused(EdgeId e, const std::vector<bool>& used) const {
    for (const std::uint32_t s : ends_[static_cast<std::size_t>(e)])
      if (s != kNone && !used[s])
        return s;
    return kNone;
  }

  static constexpr std::uint32_t kNone = ~0u;

private:
  std::vector<std::array<std::uint32_t, 2>> ends_;
};

/// Joins the segments of one level into lines: open lines from the edges with one segment
/// (the grid's border) first, then the loops.
void joinSegments(const Grid& g, const std::vector<Segment>& segments, double level, EdgeEnds& ends,
                  std::vector<ContourLine>& out) {
  ends.fill(segments);
  std::vector<bool> used(segments.size(), false);
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t first = 0; first < segments.size(); ++first) {
      if (used[first])
        continue;
      const Segment& seg = segments[first];
      if (pass == 0 && ends.degree(seg.a) != 1 && ends.degree(seg.b) != 1)
        continue;
      const EdgeId start = pass == 0 && ends.degree(seg.a) != 1 ? seg.b : seg.a;
      ContourLine line;
      line.elevation = level;
      line.points.push_back(g.point(start, level));
      EdgeId cur = start;
      for (std::uint32_t s = static_cast<std::uint32_t>(first); s != EdgeEnds::kNone;) {
        used[s] = true;
        const EdgeId next = segments[s].a == cur ? segments[s].b : segments[s].a;
        if (next == start) {
          line.closed = true;
          break;
        }
        line.points.push_back(g.point(next, level));
        cur = next;
        s = ends.unused(cur, used);
      }
      out.push_back(std::move(line));
    }
  ends.clear(segments);
}

} // namespace

std::vector<double> contourLevels(double lo, double hi, double interval) {
  STRAHLER_ASSERT(interval > 0.0, "a contour interval must be positive");
  std::vector<double> levels;
  if (!(lo <= hi))
    return levels;
  for (double k = std::floor(lo / interval) + 1.0; k * interval <= hi; k += 1.0)
    levels.push_back(k * interval);
  return levels;
}

std::vector<ContourLine> traceContours(std::span<const double> heights, int width, int height,
                                       std::span<const double> levels) {
  STRAHLER_ASSERT(width >= 0 && height >= 0 &&
                      heights.size() ==
                          static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                  "the heights must fill the grid");
  STRAHLER_ASSERT(std::is_sorted(levels.begin(), levels.end()), "levels must ascend");
  const Grid g(heights, width);
  // One pass over the cells: each adds its segments to the levels in (its lowest corner, its
  // highest], the only ones that cross it.
  std::vector<std::vector<Segment>> byLevel(levels.size());
  for (int j = 0; j + 1 < height; ++j)
    for (int i = 0; i + 1 < width; ++i) {
      const auto [lo, hi] =
          std::minmax({g.at(i, j), g.at(i + 1, j), g.at(i + 1, j + 1), g.at(i, j + 1)});
      for (auto l = std::upper_bound(levels.begin(), levels.end(), lo);
           l != levels.end() && *l <= hi; ++l)
        cellSegments(g, i, j, *l, byLevel[static_cast<std::size_t>(l - levels.begin())]);
    }
  std::vector<ContourLine> lines;
  EdgeEnds ends(2 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (std::size_t k = 0; k < levels.size(); ++k)
    joinSegments(g, byLevel[k], levels[k], ends, lines);
  return lines;
}

} // namespace strahler::render
