#pragma once
// Which tiles `strahler export` writes: the Web Mercator tiles of a zoom range that touch the
// world's bounds (intersected with --bbox), and the parsing of those options.

#include "world_bounds.h"

#include "strahler/base/result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace strahler::app {

/// The tiles of one zoom inside a box: columns x0..x1, rows y0..y1 (inclusive, XYZ rows).
struct TileRect {
  int z = 0;
  std::uint32_t x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  /// Number of tiles.
  std::uint64_t count() const noexcept {
    return std::uint64_t{x1 - x0 + 1} * std::uint64_t{y1 - y0 + 1};
  }
};

/// Parses --zooms "A-B" or "Z" with 0 ≤ A ≤ B ≤ maxZoom; the error says what is wrong.
base::Result<std::pair<int, int>> parseZoomRange(const std::string& text, int maxZoom);
/// Parses --bbox "W,S,E,N" in degrees (W < E, S < N, within ±180 / ±90).
base::Result<LonLatBox> parseBbox(const std::string& text);
/// The overlap of two boxes, if they overlap.
std::optional<LonLatBox> intersect(const LonLatBox& a, const LonLatBox& b);
/// "W,S,E,N" with 5 decimals, for messages.
std::string describe(const LonLatBox& box);

/// The tile rectangle of each zoom in [minZoom, maxZoom] touching `box`.
std::vector<TileRect> tileRects(const LonLatBox& box, int minZoom, int maxZoom);
/// Tiles in all rectangles.
std::uint64_t countTiles(const std::vector<TileRect>& rects);
/// PMTiles (Hilbert) tile ids of every tile of `rects`, ascending: the order of the archive.
std::vector<std::uint64_t> hilbertOrder(const std::vector<TileRect>& rects);

} // namespace strahler::app
