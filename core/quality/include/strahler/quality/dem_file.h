#pragma once

#include "strahler/base/result.h"
#include "strahler/quality/drainage.h"

#include <cstddef>
#include <optional>
#include <string>

namespace strahler::quality {

/// Most cells a DEM may have (20000²): larger files are refused before any value is stored.
inline constexpr std::size_t kMaxDemCells = std::size_t(20000) * 20000;

/// Reads an ESRI ASCII grid: header keys `ncols`, `nrows`, `xllcorner`/`xllcenter`,
/// `yllcorner`/`yllcenter`, `cellsize` and the optional `NODATA_value` (any case, any order),
/// then ncols·nrows numbers, north row first. NODATA cells become CellClass::kSea (outside),
/// every other cell land. Errors name the file and line: a missing, repeated or unknown key, a
/// non-numeric or non-finite value, a wrong count of values, more than kMaxDemCells cells.
base::Result<HeightRaster> readEsriAsciiGrid(const std::string& path);

/// An ASCII grid whose cellsize is below this is in degrees (as blind_set.py decides).
inline constexpr double kDegreeCellLimit = 0.01;

/// A grid in degrees (cellsize, origin in degrees) resampled as blind_set.py's square_cells():
/// cells of cellsize·40075016.686/360 metres; columns resampled by cos(latitude of the grid's
/// middle row), heights linearly, the land/outside class from the nearest column
/// (scipy.ndimage.zoom's orders 1 and 0 along the rows); the origin in metres of an
/// equirectangular frame at that latitude.
HeightRaster squareDegreeCells(const HeightRaster& grid);

/// Reads a DEM: an ESRI ASCII grid when the file starts with one of its header keys, else any
/// raster OpenImageIO reads (first channel, values as stored, metres; every cell land), which
/// needs `cellSize`. A given `cellSize` (metres, > 0) also replaces an ASCII grid's own;
/// without one, an ASCII grid in degrees (cellsize < kDegreeCellLimit) is resampled to square
/// metric cells by squareDegreeCells.
base::Result<HeightRaster> readDemFile(const std::string& path, std::optional<double> cellSize);

} // namespace strahler::quality
