#include "export_plan.h"

#include "hilbert_tile_id.h"

#include "strahler/geometry/web_mercator.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace strahler::app {
namespace {

using base::ErrorCode;
using base::makeError;

/// Column coordinate of a longitude at zoom z, in tiles (fractional).
double tileX(double lon, int z) {
  return geometry::webMercatorUnit({lon, 0.0}).x * std::ldexp(1.0, z);
}

/// Row coordinate of a latitude at zoom z, in tiles from the north (fractional).
double tileY(double lat, int z) {
  return geometry::webMercatorUnit({0.0, lat}).y * std::ldexp(1.0, z);
}

/// Tiles [first, last] covering [lo, hi) in tile coordinates: an edge exactly on a tile border
/// does not pull in the next tile.
std::pair<std::uint32_t, std::uint32_t> span(double lo, double hi, int z) {
  const double n = std::ldexp(1.0, z);
  const double first = std::clamp(std::floor(lo), 0.0, n - 1);
  const double last = std::clamp(std::ceil(hi) - 1.0, first, n - 1);
  return {static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last)};
}

bool parseInt(std::string_view text, int& out) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size();
}

} // namespace

base::Result<std::pair<int, int>> parseZoomRange(const std::string& text, int maxZoom) {
  const auto bad = [&](const std::string& why) {
    return makeError(ErrorCode::kInvalidInput, "--zooms '" + text + "': " + why +
                                                   " (expected A-B or Z with 0 <= A <= B <= " +
                                                   std::to_string(maxZoom) + ", e.g. 0-14)");
  };
  const std::size_t dash = text.find('-');
  int lo = 0, hi = 0;
  if (dash == std::string::npos) {
    if (!parseInt(text, lo))
      return bad("not a zoom range");
    hi = lo;
  } else if (!parseInt(std::string_view(text).substr(0, dash), lo) ||
             !parseInt(std::string_view(text).substr(dash + 1), hi)) {
    return bad("not a zoom range");
  }
  if (lo < 0 || hi > maxZoom)
    return bad("zoom outside 0.." + std::to_string(maxZoom));
  if (lo > hi)
    return bad("the first zoom is above the last");
  return std::pair{lo, hi};
}

base::Result<LonLatBox> parseBbox(const std::string& text) {
  double v[4] = {0, 0, 0, 0};
  std::size_t start = 0;
  for (int i = 0; i < 4; ++i) {
    const std::size_t comma = i < 3 ? text.find(',', start) : text.size();
    if (comma == std::string::npos)
      break;
    const char* first = text.data() + start;
    const char* last = text.data() + comma;
    const auto [end, ec] = std::from_chars(first, last, v[i]);
    if (ec != std::errc() || end != last || !std::isfinite(v[i]))
      return makeError(ErrorCode::kInvalidInput,
                       "--bbox '" + text + "': expected four numbers W,S,E,N in degrees");
    start = comma + 1;
    if (i == 3) {
      const LonLatBox box{v[0], v[1], v[2], v[3]};
      if (box.west < -180 || box.east > 180 || box.south < -90 || box.north > 90)
        return makeError(ErrorCode::kInvalidInput,
                         "--bbox '" + text + "': longitudes must be in [-180, 180], latitudes " +
                             "in [-90, 90]");
      if (box.west >= box.east || box.south >= box.north)
        return makeError(ErrorCode::kInvalidInput,
                         "--bbox '" + text + "': W must be less than E and S less than N");
      return box;
    }
  }
  return makeError(ErrorCode::kInvalidInput,
                   "--bbox '" + text + "': expected four numbers W,S,E,N in degrees");
}

std::optional<LonLatBox> intersect(const LonLatBox& a, const LonLatBox& b) {
  const LonLatBox c{std::max(a.west, b.west), std::max(a.south, b.south), std::min(a.east, b.east),
                    std::min(a.north, b.north)};
  if (c.west >= c.east || c.south >= c.north)
    return std::nullopt;
  return c;
}

std::string describe(const LonLatBox& box) {
  char text[96];
  std::snprintf(text, sizeof text, "%.5f,%.5f,%.5f,%.5f", box.west, box.south, box.east, box.north);
  return text;
}

std::vector<TileRect> tileRects(const LonLatBox& box, int minZoom, int maxZoom) {
  std::vector<TileRect> rects;
  for (int z = minZoom; z <= maxZoom; ++z) {
    const auto [x0, x1] = span(tileX(box.west, z), tileX(box.east, z), z);
    const auto [y0, y1] = span(tileY(box.north, z), tileY(box.south, z), z);
    rects.push_back({z, x0, x1, y0, y1});
  }
  return rects;
}

std::uint64_t countTiles(const std::vector<TileRect>& rects) {
  std::uint64_t n = 0;
  for (const TileRect& r : rects)
    n += r.count();
  return n;
}

std::vector<std::uint64_t> hilbertOrder(const std::vector<TileRect>& rects) {
  std::vector<std::uint64_t> ids;
  ids.reserve(countTiles(rects));
  for (const TileRect& r : rects) {
    const std::size_t first = ids.size();
    for (std::uint32_t y = r.y0; y <= r.y1; ++y)
      for (std::uint32_t x = r.x0; x <= r.x1; ++x)
        ids.push_back(archive::zxyToTileId({r.z, x, y}));
    // Every id of zoom z is below those of z + 1: sorting each zoom alone sorts them all.
    std::sort(ids.begin() + static_cast<std::ptrdiff_t>(first), ids.end());
  }
  return ids;
}

} // namespace strahler::app
