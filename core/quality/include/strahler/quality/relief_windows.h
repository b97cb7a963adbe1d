#pragma once

#include "strahler/quality/drainage.h"
#include "strahler/quality/geomorphons.h"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace strahler::quality {

/// Default side of the relief windows, km (blind_set.py's --window-km).
inline constexpr double kReliefWindowKm = 7.5;
/// Default number of windows (blind_set.py's --per-source).
inline constexpr int kReliefWindowCount = 3;

/// A square window of a raster, in blind_set.py's coordinates: row counted from the north
/// edge (the raster's last row), col from the west.
struct WindowPlacement {
  int row = 0;         ///< First row from the north.
  int col = 0;         ///< First column from the west.
  double reliefM = 0.; ///< Highest minus lowest height in the window, metres.
};

/// The figures of one window.
struct ReliefWindow {
  WindowPlacement placement;
  double spectralSlope = std::numeric_limits<double>::quiet_NaN(); ///< NaN if undefined.
  GeomorphonShares geomorphons = noGeomorphonShares();             ///< windowGeomorphonShares.
};

/// The window figures of a raster.
struct ReliefWindows {
  int cells = 0;                  ///< Window side, cells.
  double cellSize = 0.0;          ///< Cell side of the raster the windows were taken from, m.
  std::vector<ReliefWindow> list; ///< Highest relief first.
  /// Mean of the windows' shares; NaN without windows.
  GeomorphonShares meanGeomorphons = noGeomorphonShares();
  /// Median over the windows with a spectral slope; NaN without.
  double medianSpectralSlope = std::numeric_limits<double>::quiet_NaN();
};

/// A raster's window figures beside those of a reference DEM, windows of the same size.
struct WindowComparison {
  std::string dem;          ///< The reference's path.
  double demCellSize = 0.0; ///< Its cell, metres: compare rasters of the same cell.
  ReliefWindows demWindows; ///< Its windows.
  /// geomorphonDistance between the two mean shares (half L1, 0..1); NaN if either has none.
  double geomorphonDistance = std::numeric_limits<double>::quiet_NaN();
  /// The raster's median spectral slope minus the DEM's; NaN if either has none.
  double spectralSlopeDifference = std::numeric_limits<double>::quiet_NaN();
};

/// Compares `windows` with a DEM's (`demWindows`, of `dem` at `demCellSize` metres).
WindowComparison compareReliefWindows(const ReliefWindows& windows, const std::string& dem,
                                      double demCellSize, const ReliefWindows& demWindows);

/// blind_set.py's windows(): candidate squares of `cells` cells every max(4, cells / 8) rows and
/// columns from the north-west corner, those wholly on land, by decreasing relief (ties: larger
/// row, then larger col first); greedily kept when they overlap none kept before (row or col
/// at least `cells` apart), at most `count`.
std::vector<WindowPlacement> selectReliefWindows(const HeightRaster& raster, int cells, int count);

/// The heights of a window, north row first (as blind_set.py holds them), row-major.
std::vector<double> windowHeights(const HeightRaster& raster, const WindowPlacement& placement,
                                  int cells);

/// The raster resampled to cells of `cellSize` metres as blind_set.py does (scipy.ndimage.zoom
/// by old/new cell, orders 1 and 0): round(n · old/new) cells per axis (half to even), output
/// cell j sampling input position j·(n_in − 1)/(n_out − 1) on each axis, heights bilinearly.
/// A cell is land when its nearest input cell and every input cell its height mixes are land
/// (the script mixes NODATA values into heights there).
HeightRaster resampleRaster(const HeightRaster& raster, double cellSize);

/// Selects up to `count` windows of round(sizeKm · 1000 / cellSize) cells and measures their
/// spectral slope and geomorphon shares (blind_set.py's figures()).
ReliefWindows measureReliefWindows(const HeightRaster& raster, double sizeKm = kReliefWindowKm,
                                   int count = kReliefWindowCount,
                                   const GeomorphonParams& params = {});

} // namespace strahler::quality
