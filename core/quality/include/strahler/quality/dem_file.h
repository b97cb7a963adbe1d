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

/// Reads a DEM: an ESRI ASCII grid when the file starts with one of its header keys, else any
/// raster OpenImageIO reads (first channel, values as stored, metres; every cell land), which
/// needs `cellSize`. A given `cellSize` (metres, > 0) also replaces an ASCII grid's own.
base::Result<HeightRaster> readDemFile(const std::string& path, std::optional<double> cellSize);

} // namespace strahler::quality
