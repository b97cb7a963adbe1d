#include "strahler/quality/drainage.h"

#include "d8_grid.h"

#include "strahler/base/assert.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

namespace strahler::quality {
namespace {

using d8::Cell;
using d8::kDiagonal;
using d8::kDx;
using d8::kDy;
constexpr Cell kNoCell = std::numeric_limits<Cell>::max();

/// Working state of a land cell; water cells stay kUnresolved and are never looked at.
enum class State : std::uint8_t { kUnresolved, kDrains, kUndrained, kShallow, kCounted };

/// Raster shape and neighbour enumeration.
class Grid {
public:
  explicit Grid(const HeightRaster& raster) : raster_(raster) {}

  std::size_t size() const noexcept {
    return std::size_t(raster_.width) * std::size_t(raster_.height);
  }
  bool isLand(Cell c) const noexcept { return d8::isLand(raster_, c); }

  /// Calls fn(neighbour, k) for each of the 8 neighbours inside the raster (k indexes kDx).
  template <class Fn> void forEachNeighbour(Cell c, Fn&& fn) const {
    d8::forEachNeighbour(raster_.width, raster_.height, c, fn);
  }

  /// True if c is on the border or has a water neighbour.
  bool touchesSink(Cell c) const { return d8::touchesSink(raster_, c); }

private:
  const HeightRaster& raster_;
};

/// Result of the priority-flood over land cells.
struct Flood {
  std::vector<float> level;   ///< Spill elevation S; later the filled surface F.
  std::vector<Cell> order;    ///< Rank at which the flood reached each land cell.
  std::vector<Cell> sequence; ///< Land cells in flood order (non-decreasing S).
  std::vector<State> state;   ///< Per-cell working state.
};

struct OpenEntry {
  float level;
  Cell sequence; ///< Push counter: FIFO among equal levels, so flats are crossed breadth-first.
  Cell cell;
};

struct HigherFirst {
  bool operator()(const OpenEntry& a, const OpenEntry& b) const noexcept {
    return a.level > b.level || (a.level == b.level && a.sequence > b.sequence);
  }
};

/// Priority-flood (Barnes et al. 2014) seeded with every land cell touching a sink, which drains.
/// One heap ordered by (level, push count) instead of Barnes' separate FIFO for flats: flats are
/// then crossed breadth-first from all their outlets at once, so the flood order is a proper
/// ε-gradient toward the nearest outlet.
Flood floodFromSinks(const Grid& grid, const std::vector<float>& heights) {
  const std::size_t n = grid.size();
  Flood flood{std::vector<float>(heights),
              std::vector<Cell>(n, kNoCell),
              {},
              std::vector<State>(n, State::kUnresolved)};
  std::priority_queue<OpenEntry, std::vector<OpenEntry>, HigherFirst> open;
  std::vector<bool> queued(n, false);
  Cell pushes = 0;
  for (Cell c = 0; c < Cell(n); ++c) {
    if (grid.isLand(c) && grid.touchesSink(c)) {
      queued[c] = true;
      flood.state[c] = State::kDrains;
      open.push({heights[c], pushes++, c});
    }
  }
  while (!open.empty()) {
    const Cell c = open.top().cell;
    open.pop();
    flood.order[c] = Cell(flood.sequence.size());
    flood.sequence.push_back(c);
    grid.forEachNeighbour(c, [&](Cell nb, std::size_t) {
      if (queued[nb] || !grid.isLand(nb))
        return;
      queued[nb] = true;
      flood.level[nb] = std::max(heights[nb], flood.level[c]);
      open.push({flood.level[nb], pushes++, nb});
    });
  }
  return flood;
}

/// Finds the depressions (connected cells below their spill level); marks the cells of pits
/// undrained and lowers their F back to the terrain. Returns the number of pits.
std::size_t markPits(const Grid& grid, const std::vector<float>& heights, Flood& flood,
                     double fillTolerance) {
  std::size_t pits = 0;
  std::vector<Cell> component;
  const auto flooded = [&](Cell c) {
    return grid.isLand(c) && flood.state[c] == State::kUnresolved && flood.level[c] > heights[c];
  };
  for (Cell start = 0; start < Cell(grid.size()); ++start) {
    if (!flooded(start))
      continue;
    component.assign(1, start);
    flood.state[start] = State::kShallow;
    float lowest = heights[start];
    for (std::size_t i = 0; i < component.size(); ++i) {
      const Cell c = component[i];
      lowest = std::min(lowest, heights[c]);
      grid.forEachNeighbour(c, [&](Cell nb, std::size_t) {
        if (flooded(nb)) {
          flood.state[nb] = State::kShallow;
          component.push_back(nb);
        }
      });
    }
    if (double(flood.level[start]) - double(lowest) <= fillTolerance)
      continue;
    ++pits;
    for (Cell c : component) {
      flood.state[c] = State::kUndrained;
      flood.level[c] = heights[c];
    }
  }
  return pits;
}

/// The neighbour steepest descent on F moves to from c, which must be inland (all 8
/// neighbours exist and are land) and outside pits.
Cell descentTarget(const Grid& grid, const Flood& flood, Cell c) {
  Cell target = kNoCell;
  double steepest = 0.0;
  grid.forEachNeighbour(c, [&](Cell nb, std::size_t k) {
    const double run = (kDx[k] != 0 && kDy[k] != 0) ? kDiagonal : 1.0;
    const double slope = (double(flood.level[nb]) - double(flood.level[c])) / run;
    if (slope < steepest) {
      steepest = slope;
      target = nb;
    }
  });
  if (target != kNoCell)
    return target;
  Cell first = flood.order[c];
  grid.forEachNeighbour(c, [&](Cell nb, std::size_t) {
    if (flood.level[nb] == flood.level[c] && flood.order[nb] < first) {
      first = flood.order[nb];
      target = nb;
    }
  });
  return target;
}

/// Resolves every remaining land cell in flood order: its descent target is either in a pit,
/// or lower on F, or equal and reached earlier, so it is always resolved first.
void resolveDescent(const Grid& grid, Flood& flood) {
  for (Cell c : flood.sequence) {
    const State s = flood.state[c];
    if (s == State::kDrains || s == State::kUndrained)
      continue;
    const Cell target = descentTarget(grid, flood, c);
    STRAHLER_ASSERT(target != kNoCell, "a land cell outside pits has no way down");
    const State outcome = flood.state[target];
    STRAHLER_ASSERT(outcome == State::kDrains || outcome == State::kUndrained,
                    "descent target resolved after its source");
    flood.state[c] = outcome;
  }
}

/// The largest 8-connected set of undrained cells: its size in cells and its lowest cell (where
/// its water ends); marks every undrained cell kCounted.
struct UndrainedArea {
  std::size_t cells = 0;
  Cell lowest = kNoCell;
};
UndrainedArea largestUndrainedComponent(const Grid& grid, const std::vector<float>& heights,
                                        std::vector<State>& state) {
  UndrainedArea largest;
  std::vector<Cell> component;
  for (Cell start = 0; start < Cell(grid.size()); ++start) {
    if (state[start] != State::kUndrained)
      continue;
    component.assign(1, start);
    state[start] = State::kCounted;
    for (std::size_t i = 0; i < component.size(); ++i) {
      grid.forEachNeighbour(component[i], [&](Cell nb, std::size_t) {
        if (state[nb] == State::kUndrained) {
          state[nb] = State::kCounted;
          component.push_back(nb);
        }
      });
    }
    if (component.size() > largest.cells) {
      largest.cells = component.size();
      largest.lowest = *std::min_element(component.begin(), component.end(),
                                         [&](Cell a, Cell b) { return heights[a] < heights[b]; });
    }
  }
  return largest;
}

std::vector<CellDrainage> toCellDrainage(const Grid& grid, const std::vector<State>& state) {
  std::vector<CellDrainage> cells(grid.size(), CellDrainage::kWater);
  for (Cell c = 0; c < Cell(grid.size()); ++c) {
    if (grid.isLand(c))
      cells[c] = state[c] == State::kDrains ? CellDrainage::kDrains : CellDrainage::kUndrained;
  }
  return cells;
}

/// The whole check; fills `cells` with the per-cell outcome when it is not null.
DrainageReport analyseDrainage(const HeightRaster& raster, double fillTolerance,
                               std::vector<CellDrainage>* cells) {
  STRAHLER_ASSERT(raster.width >= 0 && raster.height >= 0, "negative raster size");
  const Grid grid(raster);
  STRAHLER_ASSERT(raster.heights.size() == grid.size() && raster.cellClass.size() == grid.size(),
                  "raster arrays do not match width * height");
  STRAHLER_ASSERT(grid.size() < std::size_t(kNoCell), "raster too large for 32-bit cell ids");
  STRAHLER_ASSERT(fillTolerance >= 0.0, "negative fill tolerance");

  Flood flood = floodFromSinks(grid, raster.heights);
  DrainageReport report;
  report.fillTolerance = fillTolerance;
  report.landCells = flood.sequence.size();
  report.pits = markPits(grid, raster.heights, flood, fillTolerance);
  resolveDescent(grid, flood);
  for (Cell c : flood.sequence)
    report.drainingCells += flood.state[c] == State::kDrains ? 1 : 0;
  report.drainingFraction =
      report.landCells == 0 ? 1.0 : double(report.drainingCells) / double(report.landCells);
  if (cells != nullptr)
    *cells = toCellDrainage(grid, flood.state);
  const double cellAreaKm2 = raster.cellSize * raster.cellSize * 1e-6;
  const UndrainedArea largest = largestUndrainedComponent(grid, raster.heights, flood.state);
  report.largestUndrainedAreaKm2 = double(largest.cells) * cellAreaKm2;
  if (largest.lowest != kNoCell)
    report.largestUndrainedAt =
        raster.origin + geometry::Vec2{double(largest.lowest % Cell(raster.width)),
                                       double(largest.lowest / Cell(raster.width))} *
                            raster.cellSize;
  return report;
}

} // namespace

DrainageMap mapDrainage(const HeightRaster& raster, double fillTolerance) {
  DrainageMap map;
  map.report = analyseDrainage(raster, fillTolerance, &map.cells);
  return map;
}

DrainageReport checkDrainage(const HeightRaster& raster, double fillTolerance) {
  return analyseDrainage(raster, fillTolerance, nullptr);
}

} // namespace strahler::quality
