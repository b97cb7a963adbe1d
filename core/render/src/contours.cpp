#include "strahler/render/contours.h"

#include "strahler/base/assert.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace strahler::render {
namespace {

/// A grid edge: 2·(row · width + column) for the edge east of a sample, +1 for the one south.
using EdgeId = std::int64_t;

struct Segment {
  EdgeId a = 0, b = 0;
};

class LevelTracer {
public:
  LevelTracer(std::span<const double> heights, int width, int height, double level)
      : h_(heights), w_(width), rows_(height), level_(level) {}

  void trace(std::vector<ContourLine>& out) {
    collectSegments();
    if (segments_.empty())
      return;
    std::vector<bool> used(segments_.size(), false);
    // Open lines start at an edge with one segment (the grid's border); then the loops.
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t s = 0; s < segments_.size(); ++s) {
        if (used[s])
          continue;
        const Segment& seg = segments_[s];
        if (pass == 0 && degree(seg.a) != 1 && degree(seg.b) != 1)
          continue;
        const EdgeId start = pass == 0 && degree(seg.a) != 1 ? seg.b : seg.a;
        out.push_back(walk(s, start, used));
      }
  }

private:
  double at(int i, int j) const { return h_[static_cast<std::size_t>(j) * w_ + i]; }
  bool above(int i, int j) const { return at(i, j) >= level_; }

  EdgeId east(int i, int j) const { return 2 * (static_cast<EdgeId>(j) * w_ + i); }
  EdgeId south(int i, int j) const { return east(i, j) + 1; }

  /// The crossing point of `edge`, in grid coordinates.
  geometry::Vec2 point(EdgeId edge) const {
    const EdgeId cell = edge / 2;
    const int i = static_cast<int>(cell % w_), j = static_cast<int>(cell / w_);
    const bool horizontal = edge % 2 == 0;
    const double h0 = at(i, j), h1 = horizontal ? at(i + 1, j) : at(i, j + 1);
    const double t = (level_ - h0) / (h1 - h0);
    return horizontal ? geometry::Vec2{i + t, static_cast<double>(j)}
                      : geometry::Vec2{static_cast<double>(i), j + t};
  }

  void add(EdgeId a, EdgeId b) {
    ends_[a].push_back(segments_.size());
    ends_[b].push_back(segments_.size());
    segments_.push_back({a, b});
  }

  std::size_t degree(EdgeId e) const {
    const auto it = ends_.find(e);
    return it == ends_.end() ? 0 : it->second.size();
  }

  void collectSegments() {
    for (int j = 0; j + 1 < rows_; ++j)
      for (int i = 0; i + 1 < w_; ++i) {
        // Corners 0 north-west, 1 north-east, 2 south-east, 3 south-west; edges between them.
        const int mask = (above(i, j) ? 1 : 0) | (above(i + 1, j) ? 2 : 0) |
                         (above(i + 1, j + 1) ? 4 : 0) | (above(i, j + 1) ? 8 : 0);
        if (mask == 0 || mask == 15)
          continue;
        const EdgeId n = east(i, j), e = south(i + 1, j), s = east(i, j + 1), w = south(i, j);
        switch (mask) {
        case 1: case 14: add(w, n); break;
        case 2: case 13: add(n, e); break;
        case 3: case 12: add(w, e); break;
        case 4: case 11: add(e, s); break;
        case 6: case 9: add(n, s); break;
        case 7: case 8: add(w, s); break;
        case 5: case 10: {
          const double mean = 0.25 * (at(i, j) + at(i + 1, j) + at(i + 1, j + 1) + at(i, j + 1));
          // Corners 0 and 2 above (5) joined through the centre when the mean is above too.
          if ((mask == 5) == (mean >= level_)) {
            add(w, s);
            add(n, e);
          } else {
            add(w, n);
            add(e, s);
          }
          break;
        }
        default:
          break;
        }
      }
  }

  ContourLine walk(std::size_t first, EdgeId start, std::vector<bool>& used) {
    ContourLine line;
    line.elevation = level_;
    line.points.push_back(point(start));
    EdgeId at = start;
    std::size_t s = first;
    for (;;) {
      used[s] = true;
      const EdgeId next = segments_[s].a == at ? segments_[s].b : segments_[s].a;
      if (next == start) {
        line.closed = true;
        break;
      }
      line.points.push_back(point(next));
      at = next;
      std::size_t follow = segments_.size();
      for (std::size_t candidate : ends_[at])
        if (!used[candidate])
          follow = candidate;
      if (follow == segments_.size())
        break;
      s = follow;
    }
    return line;
  }

  std::span<const double> h_;
  int w_ = 0, rows_ = 0;
  double level_ = 0.0;
  std::vector<Segment> segments_;
  std::unordered_map<EdgeId, std::vector<std::size_t>> ends_;
};

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
                  heights.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                  "the heights must fill the grid");
  std::vector<ContourLine> lines;
  for (const double level : levels)
    LevelTracer(heights, width, height, level).trace(lines);
  return lines;
}

} // namespace strahler::render
