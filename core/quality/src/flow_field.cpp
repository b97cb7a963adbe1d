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

} // namespace strahler::quality
