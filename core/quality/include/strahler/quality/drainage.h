#pragma once

#include "strahler/geometry/vec2.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace strahler::quality {

/// What a raster cell holds (HeightRaster::cellClass values).
enum class CellClass : std::uint8_t {
  kLand = 0, ///< Ground: the cells whose drainage is checked.
  kSea = 1,  ///< Sea: a sink.
  kLake = 2, ///< Lake surface: a sink, like the sea.
  /// Ground the shoreline crosses (within half a cell of it): land for every figure, and an
  /// outlet, since its water reaches the sea or a lake inside the cell (a fjord or channel
  /// narrower than a cell has no water cell of its own).
  kShore = 3,
};

/// A regular grid of terrain heights. Invariant: heights.size() == cellClass.size() ==
/// width * height, cell (x, y) at index y * width + x.
struct HeightRaster {
  int width = 0;              ///< Cells per row.
  int height = 0;             ///< Rows.
  double cellSize = 1;        ///< Cell side, metres.
  geometry::Vec2 origin;      ///< Centre of cell (0, 0), local metres; row 0 is the southernmost.
  std::vector<float> heights; ///< Metres above sea level, one per cell.
  std::vector<std::uint8_t> cellClass; ///< One CellClass value per cell.
};

/// Summary of checkDrainage. Only land cells are counted.
struct DrainageReport {
  std::size_t landCells = 0;            ///< Number of land cells.
  std::size_t drainingCells = 0;        ///< Land cells that drain (see mapDrainage).
  double drainingFraction = 1.0;        ///< drainingCells / landCells; 1 when there is no land.
  std::size_t pits = 0;                 ///< Depressions deeper than fillTolerance.
  double largestUndrainedAreaKm2 = 0.0; ///< Largest 8-connected set of undrained cells, km².
  /// Lowest cell of that set (where its water ends), local metres; (0, 0) when there is none.
  geometry::Vec2 largestUndrainedAt;
  double fillTolerance = 0.0; ///< The tolerance used, metres.
};

/// Outcome for one cell.
enum class CellDrainage : std::uint8_t {
  kWater,     ///< A sea or lake cell.
  kDrains,    ///< Land whose water reaches a sink.
  kUndrained, ///< Land whose water ends in a depression deeper than the tolerance.
};

/// A DrainageReport with the per-cell outcome behind it (same indexing as the raster).
struct DrainageMap {
  DrainageReport report;           ///< The summary.
  std::vector<CellDrainage> cells; ///< One outcome per raster cell.
};

/// Decides, for every land cell, whether its water reaches the sea, a lake or the raster border
/// (cells outside the raster count as sea). Definitions, 8-neighbour throughout:
/// - sinks: water cells and everything outside the raster. A land cell touching a sink (on the
///   border or next to a water cell) drains directly.
/// - spill elevation S(c) of a land cell: the lowest level to which water must rise at c to
///   leave it for a sink, i.e. the minimum over land paths from c to a cell touching a sink of
///   the highest cell on the path (computed by priority-flood, Barnes et al. 2014).
/// - depression: a maximal connected set of land cells with S(c) > height(c); all its cells
///   share one S (the level of the lake a full fill would make there). Its depth is
///   S − its lowest height. A depression is shallow if depth <= fillTolerance, else a pit.
/// - filled surface F: S inside shallow depressions, the height everywhere else (pits stay).
/// - a land cell drains iff it is in no pit and steepest descent on F from it reaches a cell
///   touching a sink without entering a pit. Steepest descent goes to the neighbour with the
///   largest drop per metre (diagonals sqrt 2 cells away); on a flat (no lower neighbour) it goes
///   to the equal neighbour the flood reached first. The flood crosses each flat breadth-first
///   from its outlets, so this is the ε-gradient of priority-flood+ε and always leads off the
///   flat toward its nearest outlet.
/// So pit cells and the whole catchment feeding each pit are undrained (a cell just downhill of
/// a pit is undrained too if the pit is its steepest way down); shallow depressions and flats
/// are transparent. With fillTolerance 0 every depression is a pit and this is plain D8 flow.
/// O(n log n) time, about 13 bytes per cell of working memory plus the flood front (12 per cell on
/// it), no recursion. fillTolerance is in metres and must be >= 0; the raster must satisfy its
/// invariant.
DrainageMap mapDrainage(const HeightRaster& raster, double fillTolerance = 1.0);

/// mapDrainage without the per-cell map.
DrainageReport checkDrainage(const HeightRaster& raster, double fillTolerance = 1.0);

} // namespace strahler::quality
