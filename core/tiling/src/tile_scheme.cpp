#include "strahler/tiling/tile_scheme.h"

#include "strahler/geometry/web_mercator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::tiling {
namespace {

using geometry::Vec2;

constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kWebExtent = std::numbers::pi * kWebMercatorRadius; // half the world, m
constexpr double kFinestLocalSpacing = 0.5; // m per sample at 256 samples per tile

/// Global sample coordinates along one axis: (tile · n + k + first) · step, for k < count.
std::vector<double> axis(std::int64_t tile, int n, int count, double first, double step) {
  std::vector<double> out(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k)
    out[static_cast<std::size_t>(k)] = (static_cast<double>(tile) * n + k + first) * step;
  return out;
}

geometry::Aabb boundsOf(const std::vector<Vec2>& points) {
  geometry::Aabb box;
  for (Vec2 p : points)
    box.add(p);
  return box;
}

} // namespace

TileScheme TileScheme::webMercator(const geometry::LocalProjection& projection) {
  TileScheme s;
  s.kind_ = SchemeKind::kWebMercator;
  s.maxZoom_ = kMaxWebZoom;
  s.projection_ = projection;
  return s;
}

TileScheme TileScheme::geographic(const geometry::LocalProjection& projection) {
  TileScheme s;
  s.kind_ = SchemeKind::kGeographic;
  s.maxZoom_ = kMaxGeographicZoom;
  s.projection_ = projection;
  return s;
}

TileScheme TileScheme::local(Vec2 center, double rootSide) {
  TileScheme s;
  s.kind_ = SchemeKind::kLocal;
  s.center_ = center;
  s.rootSide_ = rootSide;
  const double levels = std::floor(std::log2(rootSide / (256.0 * kFinestLocalSpacing)));
  s.maxZoom_ = static_cast<int>(std::clamp(levels, 0.0, 24.0));
  return s;
}

TileScheme TileScheme::localFor(const geometry::Aabb& landBounds) {
  const Vec2 size = landBounds.size();
  return local(landBounds.center(), 1.1 * std::max({size.x, size.y, 1.0}));
}

bool TileScheme::contains(const geometry::TileId& t) const noexcept {
  if (t.z < 0 || t.z > maxZoom_)
    return false;
  const std::int64_t n = std::int64_t{1} << t.z;
  const std::int64_t columns = kind_ == SchemeKind::kGeographic ? 2 * n : n;
  return t.x >= 0 && t.y >= 0 && t.x < columns && t.y < n;
}

geometry::Aabb TileScheme::geographicBounds(const geometry::TileId& t) const noexcept {
  const double side = 180.0 / static_cast<double>(std::int64_t{1} << t.z);
  const Vec2 northWest{-180.0 + static_cast<double>(t.x) * side,
                       90.0 - static_cast<double>(t.y) * side};
  return {{northWest.x, northWest.y - side}, {northWest.x + side, northWest.y}};
}

geometry::Aabb TileScheme::localBounds(const geometry::TileId& t) const noexcept {
  const double side = rootSide_ / static_cast<double>(std::int64_t{1} << t.z);
  const Vec2 west{center_.x - 0.5 * rootSide_ + static_cast<double>(t.x) * side,
                  center_.y + 0.5 * rootSide_ - static_cast<double>(t.y + 1) * side};
  return {west, west + Vec2{side, side}};
}

SampleGrid TileScheme::rasterGrid(const geometry::TileId& tile, int size) const {
  switch (kind_) {
  case SchemeKind::kLocal:
    return localGrid(tile, size, size, 0.5, true);
  case SchemeKind::kGeographic:
    return geographicGrid(tile, size, size, 0.5, true);
  case SchemeKind::kWebMercator:
    break;
  }
  return webGrid(tile, size, size, 0.5, true);
}

SampleGrid TileScheme::borderedRasterGrid(const geometry::TileId& tile, int size) const {
  return borderedRasterGrid(tile, size, 1);
}

SampleGrid TileScheme::borderedRasterGrid(const geometry::TileId& tile, int size,
                                          int border) const {
  // Global index tile·size + k + 0.5 − border is exact in double, as tile·size + k + 0.5 is.
  const double first = 0.5 - border;
  const int count = size + 2 * border;
  return kind_ == SchemeKind::kLocal ? localGrid(tile, size, count, first, true)
                                     : webGrid(tile, size, count, first, true);
}

SampleGrid TileScheme::meshGrid(const geometry::TileId& tile, int quads) const {
  switch (kind_) {
  case SchemeKind::kLocal:
    return localGrid(tile, quads, quads + 3, -1.0, false);
  case SchemeKind::kGeographic:
    return geographicGrid(tile, quads, quads + 3, -1.0, false);
  case SchemeKind::kWebMercator:
    break;
  }
  return webGrid(tile, quads, quads + 3, -1.0, false);
}

std::pair<Vec2, double> TileScheme::meshFrame(const geometry::TileId& tile, int quads) const {
  if (kind_ == SchemeKind::kGeographic) {
    const geometry::Aabb box = geographicBounds(tile);
    return {box.min, box.size().x / quads};
  }
  if (kind_ == SchemeKind::kLocal) {
    const geometry::Aabb box = localBounds(tile);
    return {box.min, box.size().x / quads};
  }
  const double side = 2.0 * kWebExtent / static_cast<double>(std::int64_t{1} << tile.z);
  return {{-kWebExtent + static_cast<double>(tile.x) * side,
           kWebExtent - static_cast<double>(tile.y + 1) * side},
          side / quads};
}

SampleGrid TileScheme::localGrid(const geometry::TileId& tile, int n, int count, double first,
                                 bool northFirst) const {
  const double step = rootSide_ / (static_cast<double>(std::int64_t{1} << tile.z) * n);
  const Vec2 west{center_.x - 0.5 * rootSide_, center_.y + 0.5 * rootSide_}; // north-west corner
  const std::vector<double> xs = axis(tile.x, n, count, first, step);
  SampleGrid g;
  g.width = g.height = count;
  g.points.reserve(static_cast<std::size_t>(count) * static_cast<std::size_t>(count));
  for (int j = 0; j < count; ++j) {
    // Distance from the north edge of the root square, from a global row index, so that
    // neighbouring tiles compute their shared rows identically.
    const double row = northFirst ? static_cast<double>(tile.y) * n + j + first
                                  : static_cast<double>(tile.y + 1) * n + 1.0 - j;
    const double d = row * step;
    for (int i = 0; i < count; ++i)
      g.points.push_back({west.x + xs[static_cast<std::size_t>(i)], west.y - d});
  }
  g.rowSpacing.assign(static_cast<std::size_t>(count), step);
  g.bounds = boundsOf(g.points);
  return g;
}

SampleGrid TileScheme::webGrid(const geometry::TileId& tile, int n, int count, double first,
                               bool northFirst) const {
  const double step = 2.0 * kWebExtent / (static_cast<double>(std::int64_t{1} << tile.z) * n);
  std::vector<double> lons = axis(tile.x, n, count, first, step);
  for (double& x : lons)
    x = (x - kWebExtent) / kWebMercatorRadius * kDeg;
  std::vector<double> lats(static_cast<std::size_t>(count));
  for (int j = 0; j < count; ++j) {
    // Global row index from the north edge of the world, in samples.
    const double row = northFirst ? static_cast<double>(tile.y) * n + j + first
                                  : static_cast<double>(tile.y + 1) * n + 1.0 - j;
    const double my = kWebExtent - row * step;
    lats[static_cast<std::size_t>(j)] = geometry::latitudeOfNorthing(my / kWebMercatorRadius);
  }
  SampleGrid g;
  g.width = g.height = count;
  projection_.forwardGrid(lons, lats, g.points);
  g.rowSpacing.resize(static_cast<std::size_t>(count));
  for (int j = 0; j < count; ++j)
    g.rowSpacing[static_cast<std::size_t>(j)] =
        step * std::cos(lats[static_cast<std::size_t>(j)] / kDeg);
  g.bounds = boundsOf(g.points);
  return g;
}

SampleGrid TileScheme::geographicGrid(const geometry::TileId& tile, int n, int count, double first,
                                      bool northFirst) const {
  // Degrees per sample; lon = −180 + global column · step, lat = 90 − global row · step, from
  // global indices so that neighbouring tiles compute their shared samples identically.
  const double step = 180.0 / (static_cast<double>(std::int64_t{1} << tile.z) * n);
  std::vector<double> lons = axis(tile.x, n, count, first, step);
  for (double& x : lons)
    x -= 180.0;
  std::vector<double> lats(static_cast<std::size_t>(count));
  for (int j = 0; j < count; ++j) {
    const double row = northFirst ? static_cast<double>(tile.y) * n + j + first
                                  : static_cast<double>(tile.y + 1) * n + 1.0 - j;
    lats[static_cast<std::size_t>(j)] = std::clamp(90.0 - row * step, -90.0, 90.0);
  }
  SampleGrid g;
  g.width = g.height = count;
  projection_.forwardGrid(lons, lats, g.points);
  // A quarter of the north-south distance between samples: the vertices of a level carry the
  // detail of two levels below, so that they lie within the level's geometric error of the
  // finest terrain (at the grid's own spacing the faded octaves moved them by up to 1.6 times
  // that error at level 11; docs/architecture.md, Cesium terrain).
  g.rowSpacing.assign(static_cast<std::size_t>(count), 0.25 * step / kDeg * geometry::kEarthRadius);
  g.bounds = boundsOf(g.points);
  return g;
}

} // namespace strahler::tiling
