#pragma once

#include "strahler/base/result.h"
#include "strahler/geometry/aabb.h"
#include "strahler/geometry/projection.h"
#include "strahler/geometry/tile_id.h"

#include <cstdint>
#include <vector>

namespace strahler::tiling {

/// Where to sample a tile: points in the world's local frame, row-major.
struct SampleGrid {
  int width = 0;
  int height = 0;
  std::vector<geometry::Vec2> points; ///< width · height local points.
  /// Per row: ground distance between neighbouring samples, m (the LOD knob). Constant along
  /// a row so that tiles sharing a row of samples fade the same noise octaves.
  std::vector<double> rowSpacing;
  geometry::Aabb bounds; ///< Bounding box of the points.
};

/// The two tile pyramids strahler serves.
enum class SchemeKind {
  kWebMercator, ///< EPSG:3857 XYZ tiles, for web maps.
  kLocal,       ///< A metric quadtree over the world's bounding square, for game clients.
  /// EPSG:4326 tiles of 2 × 1 roots (Cesium's quantized-mesh pyramid); geometry::TileId rows still
  /// count from the north (the TMS row of a URL is geometry::flipRow(z, y) = 2^z − 1 − y).
  kGeographic,
};

/// A tile pyramid over one world: tile bounds and the sample grids of raster and mesh tiles.
/// Raster tiles sample pixel centres, row 0 north. Mesh tiles sample (n+3)² vertices: the
/// (n+1)² edge-inclusive vertices of the tile plus a one-vertex border, row 0 south (so that
/// neighbours share their edge samples exactly).
class TileScheme {
public:
  /// The Web Mercator pyramid (zoom 0..kMaxWebZoom) seen through a world's projection.
  static TileScheme webMercator(const geometry::LocalProjection& projection);
  /// The geographic pyramid (zoom 0..kMaxGeographicZoom) seen through a world's projection.
  static TileScheme geographic(const geometry::LocalProjection& projection);
  /// The local pyramid over the square of side `rootSide` metres centred on `center`.
  static TileScheme local(geometry::Vec2 center, double rootSide);
  /// The local pyramid of a world whose land spans `landBounds`: a square 10 % larger than
  /// its longer side, zoom levels down to ~0.5 m per sample at 256 samples per tile.
  static TileScheme localFor(const geometry::Aabb& landBounds);

  /// Deepest Web Mercator zoom served (≈ 0.6 m per pixel at the equator for 256² tiles).
  static constexpr int kMaxWebZoom = 18;

  /// Deepest geographic zoom served (≈ 2.4 m between the vertices of a 64-quad mesh tile).
  static constexpr int kMaxGeographicZoom = 17;
  /// Which pyramid this is.
  SchemeKind kind() const noexcept { return kind_; }
  /// Deepest zoom level.
  int maxZoom() const noexcept { return maxZoom_; }
  /// True when the tile exists in this pyramid (zoom in range, x and y in [0, 2^z); x in
  /// [0, 2^(z+1)) for kGeographic).
  bool contains(const geometry::TileId& tile) const noexcept;
  /// The local square of a LocalQuad tile (kLocal only): its south-west corner and side, m.
  geometry::Aabb localBounds(const geometry::TileId& tile) const noexcept;

  /// The longitude/latitude box of a kGeographic tile, degrees: min = (west, south).
  geometry::Aabb geographicBounds(const geometry::TileId& tile) const noexcept;
  /// Pixel-centre samples of a `size`×`size` raster tile.
  SampleGrid rasterGrid(const geometry::TileId& tile, int size) const;
  /// rasterGrid() with a one-pixel border, (size+2)²: sample (i+1, j+1) is rasterGrid's (i, j)
  /// bit for bit, and the border holds the neighbouring tiles' edge pixels (for slopes).
  SampleGrid borderedRasterGrid(const geometry::TileId& tile, int size) const;
  /// rasterGrid() with a border of `border` ≥ 1 pixels, (size + 2·border)²: sample
  /// (i + border, j + border) is rasterGrid's (i, j) bit for bit, the border the neighbouring
  /// tiles' pixels (for layers that look beyond the tile, such as the sky view). kLocal and
  /// kWebMercator only.
  SampleGrid borderedRasterGrid(const geometry::TileId& tile, int size, int border) const;
  /// Bordered vertex samples of a mesh tile with `quads`×`quads` quads.
  SampleGrid meshGrid(const geometry::TileId& tile, int quads) const;
  /// The mesh frame of a tile: south-west corner and vertex spacing, in the scheme's own
  /// metres (local metres for kLocal, EPSG:3857 metres for kWebMercator).
  std::pair<geometry::Vec2, double> meshFrame(const geometry::TileId& tile, int quads) const;

private:
  // Samples k < count per axis at global index (tile · n + k + first), n samples per tile.
  SampleGrid webGrid(const geometry::TileId& tile, int n, int count, double first,
                     bool northFirst) const;
  SampleGrid localGrid(const geometry::TileId& tile, int n, int count, double first,
                       bool northFirst) const;
  SampleGrid geographicGrid(const geometry::TileId& tile, int n, int count, double first,
                            bool northFirst) const;

  SchemeKind kind_ = SchemeKind::kLocal;
  int maxZoom_ = 0;
  geometry::LocalProjection projection_;
  geometry::Vec2 center_{};
  double rootSide_ = 1.0;
};

/// Radius of the spherical Web Mercator (EPSG:3857), m.
inline constexpr double kWebMercatorRadius = 6378137.0;

} // namespace strahler::tiling
