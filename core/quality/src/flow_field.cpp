#include "strahler/quality/flow_field.h"

#include "d8_grid.h"

#include "strahler/base/assert.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <queue>
#include <vector>

namespace strahler::quality {
namespace {

using d8::Cell;
using d8::forEachNeighbour;
using d8::isLand;
using d8::kDx;
using d8::kDy;
using d8::touchesSink;

struct OpenEntry {
  float level;
  Cell sequence; ///< Push counter: FIFO among equal levels.
  Cell cell;
};

struct HigherFirst {
  bool operator()(const OpenEntry& a, const OpenEntry& b) const noexcept {
    return a.level > b.level || (a.level == b.level && a.sequence > b.sequence);
  }
};

/// Priority-flood+ε: raises every land cell to at least one float step above the cell that
/// reached it, so every land cell but the seeds has a strictly lower neighbour. Fills
/// flow.filled and flow.order (land cells by non-decreasing filled height).
void fillWithEpsilon(const HeightRaster& r, FlowField& flow) {
  const std::size_t n = r.heights.size();
  std::priority_queue<OpenEntry, std::vector<OpenEntry>, HigherFirst> open;
  std::vector<bool> queued(n, false);
  Cell pushes = 0;
  for (Cell c = 0; c < Cell(n); ++c)
    if (isLand(r, c) && touchesSink(r, c)) {
      queued[c] = true;
      open.push({r.heights[c], pushes++, c});
    }
  while (!open.empty()) {
    const Cell c = open.top().cell;
    open.pop();
    flow.order.push_back(c);
    const float above = std::nextafter(flow.filled[c], std::numeric_limits<float>::infinity());
    forEachNeighbour(r.width, r.height, c, [&](Cell nb, std::size_t) {
      if (queued[nb] || !isLand(r, nb))
        return;
      queued[nb] = true;
      flow.filled[nb] = std::max(r.heights[nb], above);
      open.push({flow.filled[nb], pushes++, nb});
    });
  }
}

/// The land neighbour of steepest descent on the filled heights, or kNone.
Cell steepestDescent(const HeightRaster& r, const FlowField& flow, Cell c) {
  Cell target = FlowField::kNone;
  double steepest = 0.0;
  forEachNeighbour(r.width, r.height, c, [&](Cell nb, std::size_t k) {
    if (!isLand(r, nb))
      return;
    const double run = (kDx[k] != 0 && kDy[k] != 0) ? d8::kDiagonal : 1.0;
    const double slope = (double(flow.filled[c]) - double(flow.filled[nb])) / run;
    if (slope > steepest) {
      steepest = slope;
      target = nb;
    }
  });
  return target;
}

/// Squared distances (in cells²) of one line `f` to its nearest zero, in place
/// (Felzenszwalb & Huttenlocher 2012, lower envelope of parabolas).
void transformLine(std::vector<double>& f, std::vector<int>& v, std::vector<double>& z,
                   std::vector<double>& d) {
  const int n = int(f.size());
  constexpr double kInf = std::numeric_limits<double>::infinity();
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (!std::isfinite(f[std::size_t(q)]))
      continue;
    while (k >= 0) {
      const int p = v[std::size_t(k)];
      const double s = ((f[std::size_t(q)] + double(q) * q) - (f[std::size_t(p)] + double(p) * p)) /
                       (2.0 * (q - p));
      if (s > z[std::size_t(k)])
        break;
      --k;
    }
    ++k;
    v[std::size_t(k)] = q;
    z[std::size_t(k)] = k == 0 ? -kInf
                               : ((f[std::size_t(q)] + double(q) * q) -
                                  (f[std::size_t(v[std::size_t(k - 1)])] +
                                   double(v[std::size_t(k - 1)]) * v[std::size_t(k - 1)])) /
                                     (2.0 * (q - v[std::size_t(k - 1)]));
  }
  if (k < 0)
    return; // nothing finite on this line
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (j < k && z[std::size_t(j + 1)] < q)
      ++j;
    const int p = v[std::size_t(j)];
    d[std::size_t(q)] = double(q - p) * double(q - p) + f[std::size_t(p)];
  }
  for (int q = 0; q < n; ++q)
    f[std::size_t(q)] = d[std::size_t(q)];
}

} // namespace

FlowField computeFlowField(const HeightRaster& raster) {
  const std::size_t n = std::size_t(raster.width) * std::size_t(raster.height);
  STRAHLER_ASSERT(raster.heights.size() == n && raster.cellClass.size() == n,
                  "raster arrays do not match width * height");
  STRAHLER_ASSERT(n < std::size_t(FlowField::kNone), "raster too large for 32-bit cell ids");
  FlowField flow;
  flow.width = raster.width;
  flow.height = raster.height;
  flow.cellSize = raster.cellSize;
  flow.filled = raster.heights;
  flow.receiver.assign(n, FlowField::kNone);
  flow.areaKm2.assign(n, 0.0);
  flow.order.reserve(n);
  fillWithEpsilon(raster, flow);
  const double cellKm2 = raster.cellSize * raster.cellSize * 1e-6;
  for (Cell c : flow.order) {
    // Outlets: their water leaves the raster or enters the water next to them.
    flow.receiver[c] = touchesSink(raster, c) ? FlowField::kNone : steepestDescent(raster, flow, c);
    STRAHLER_ASSERT(flow.receiver[c] != FlowField::kNone || touchesSink(raster, c),
                    "an ε-filled land cell has no lower neighbour");
    flow.areaKm2[c] = cellKm2;
  }
  // Receivers are strictly lower, hence earlier in flood order: accumulate from the top.
  for (auto it = flow.order.rbegin(); it != flow.order.rend(); ++it)
    if (flow.receiver[*it] != FlowField::kNone)
      flow.areaKm2[flow.receiver[*it]] += flow.areaKm2[*it];
  return flow;
}

double stepLength(const FlowField& flow, std::uint32_t from, std::uint32_t to) noexcept {
  if (to == FlowField::kNone)
    return flow.cellSize;
  const bool diagonal = from % Cell(flow.width) != to % Cell(flow.width) &&
                        from / Cell(flow.width) != to / Cell(flow.width);
  return diagonal ? flow.cellSize * d8::kDiagonal : flow.cellSize;
}

std::vector<float> distanceToMarked(int width, int height, double cellSize,
                                    const std::vector<std::uint8_t>& marked) {
  const std::size_t w = std::size_t(width), h = std::size_t(height);
  STRAHLER_ASSERT(marked.size() == w * h, "mask does not match width * height");
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<float> out(w * h);
  const std::size_t longest = std::max(w, h);
  std::vector<double> f(longest), d(longest), z(longest + 1);
  std::vector<int> v(longest);
  std::vector<double> columns(w * h);
  for (std::size_t x = 0; x < w; ++x) {
    f.resize(h), d.resize(h);
    for (std::size_t y = 0; y < h; ++y)
      f[y] = marked[y * w + x] != 0 ? 0.0 : kInf;
    transformLine(f, v, z, d);
    for (std::size_t y = 0; y < h; ++y)
      columns[y * w + x] = f[y];
  }
  for (std::size_t y = 0; y < h; ++y) {
    f.assign(columns.begin() + std::ptrdiff_t(y * w), columns.begin() + std::ptrdiff_t(y * w + w));
    d.resize(w);
    transformLine(f, v, z, d);
    for (std::size_t x = 0; x < w; ++x)
      out[y * w + x] = float(std::sqrt(f[x]) * cellSize);
  }
  return out;
}

} // namespace strahler::quality
