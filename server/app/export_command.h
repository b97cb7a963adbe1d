#pragma once

#include <string>
#include <vector>

namespace strahler::app {

/// `strahler export WORLD --zooms A-B -o FILE.pmtiles|FILE.mbtiles ...`: every Web Mercator
/// tile of the world in the zoom range, made by the server's TileService on a worker pool,
/// written to a PMTiles or MBTiles archive (FILE.tmp.PID, renamed when complete). Returns the
/// exit code: 0, 1 (failure), 2 (bad command line), or death by the signal that interrupted it.
int runExport(const std::vector<std::string>& args);

} // namespace strahler::app
