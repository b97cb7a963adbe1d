#pragma once

#include "strahler/quality/drainage.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace strahler::quality {

/// D8 flow over the land cells of a HeightRaster, on its pit-filled heights.
/// Invariant: every vector has width * height entries (raster indexing); water and outside
/// cells have no receiver, zero area and keep their height in `filled`.
struct FlowField {
  /// Marks a cell without receiver: water, or an outlet (a land cell whose water leaves).
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  int width = 0;                       ///< Cells per row.
  int height = 0;                      ///< Rows.
  double cellSize = 1;                 ///< Cell side, metres.
  std::vector<float> filled;           ///< Heights after priority-flood+ε filling, metres.
  std::vector<std::uint32_t> receiver; ///< The D8 neighbour each land cell drains to, or kNone.
  std::vector<double> areaKm2;         ///< Upstream area of each land cell, itself included.
  std::vector<std::uint32_t> order;    ///< Land cells, every receiver before its donors.
};

/// D8 flow of `raster`: the outlets are the land cells on the raster border or next to a water
/// cell (their water leaves); depressions are filled from them by priority-flood+ε (Barnes et
/// al. 2014), and every other land cell drains to the land neighbour of steepest descent (drop
/// per metre, diagonals √2 cells away) on the filled heights. Areas accumulate in km².
/// O(n log n) time, about 24 bytes per cell.
FlowField computeFlowField(const HeightRaster& raster);

/// Length in metres of the D8 step from cell `from` to its neighbour `to` (cellSize or
/// cellSize·√2); cellSize for an outlet (to == kNone).
double stepLength(const FlowField& flow, std::uint32_t from, std::uint32_t to) noexcept;

} // namespace strahler::quality
