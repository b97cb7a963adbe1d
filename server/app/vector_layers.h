#pragma once

#include "strahler/construction/world_data.h"
#include "strahler/geometry/aabb.h"
#include "strahler/geometry/projection.h"
#include "strahler/primitives/river_primitive.h"
#include "strahler/tiling/tile_scheme.h"
#include "strahler/vector_tile/tile_geometry.h"
#include "strahler/vector_tile/vector_tile.h"

#include <span>
#include <string>
#include <vector>

namespace strahler::app {

/// Tile units beyond each edge that a vector tile keeps (so that lines and fills join).
inline constexpr int kVectorBuffer = 64;
/// Douglas–Peucker tolerance of vector tile lines and rings, tile units (1/4096 of a tile, so
/// the lines are simplified per zoom: ~10 m at zoom 10, ~0.6 m at zoom 14 near the equator).
inline constexpr double kVectorTolerance = 1.0;
/// Samples per side of the grid the contours are traced on (pixel centres of a 256² raster
/// tile, plus a one-sample border shared with the neighbours).
inline constexpr int kContourGrid = 256;

/// A run of points in normalised Web Mercator ([0, 1]², x east, y south) with its box.
struct MercatorLine {
  std::vector<geometry::Vec2> points; ///< Normalised Web Mercator.
  geometry::Aabb box;                 ///< Bounding box of the points.
  /// Rings only: the boxes of runs of kRingChunk edges (the closing edge in the last), so that
  /// a tile the ring's boundary does not enter skips its clipping.
  std::vector<geometry::Aabb> chunks;
};

/// Edges per box of MercatorLine::chunks.
inline constexpr std::size_t kRingChunk = 64;

/// A river section of the world (render::forEachRiverSection) in normalised Web Mercator.
struct MercatorRiver {
  MercatorLine line;                                               ///< Upstream first.
  int order = 1;                                                   ///< Strahler order.
  double flow = 0.0;                                               ///< m³/s, downstream end.
  double width = 0.0;                                              ///< Channel width downstream, m.
  primitives::RiverType rosgen = primitives::RiverType::kStraight; ///< Rosgen type.
};

/// A land polygon in normalised Web Mercator: its outline and its lakes.
struct MercatorPolygon {
  MercatorLine outer;              ///< The coast (closing point implicit).
  std::vector<MercatorLine> holes; ///< The lakes' shores.
};

/// The vector geometry of a world, projected once: the rivers, the land and the artist's map.
struct WorldVectors {
  std::vector<MercatorRiver> rivers;         ///< Every river section.
  std::vector<MercatorPolygon> land;         ///< The land polygons.
  int maxOrder = 1;                          ///< The largest Strahler order of the world.
  const input::Features* features = nullptr; ///< The artist's vector map (the world's).
};

/// `world`'s vector geometry through `projection` (its local frame to longitude/latitude).
WorldVectors projectWorldVectors(const construction::WorldData& world,
                                 const geometry::LocalProjection& projection);

/// The smallest Strahler order drawn at zoom `z`: 13 − z, at least 1, and at most the world's
/// largest order (so its main rivers show at every zoom). Every order from zoom 12 on.
int minRiverOrder(int z, int maxOrder) noexcept;

/// The contour interval at zoom `z`, m: 1000 up to zoom 7, 500 at 8, 200 at 9, 100 at 10–11,
/// 50 at 12, 20 at 13, 10 at 14–15, 5 from 16. Every fifth level is an index contour.
double contourInterval(int z) noexcept;

/// The `rivers` layer of `tile`: sections of the orders visible at its zoom, clipped to the
/// tile and its buffer, simplified; attributes order, flow, width, rosgen.
vector_tile::Layer riversLayer(const WorldVectors& world, const geometry::TileId& tile);

/// The `water` layer of `tile`: the sea (the tile and its buffer minus the land, kind "sea")
/// and the lakes (the land's holes, kind "lake"), clipped, exteriors clockwise in tile units.
vector_tile::Layer waterLayer(const WorldVectors& world, const geometry::TileId& tile);

/// The `features` layer of `tile`: the artist's mountains (points) and ridges and rivers
/// (lines), with attributes kind and, when drawn, name, elevation and radius.
vector_tile::Layer featuresLayer(const WorldVectors& world, const geometry::TileId& tile);

/// The `contours` layer of a tile from `heights`, the kContourGrid² pixel-centre samples of
/// its raster grid plus a one-sample border ((kContourGrid + 2)², borderedRasterGrid): the
/// levels above 0 m at contourInterval(z), attributes elevation (m) and index (every fifth).
vector_tile::Layer contoursLayer(std::span<const double> heights, int z);

/// The TileJSON vector_layers array of the vector tiles (id, fields, minzoom, maxzoom,
/// description), as JSON text, each layer over zooms `minZoom`..`maxZoom`.
std::string vectorLayersJson(int minZoom, int maxZoom);

/// The TileJSON 3.0.0 document of world `id`'s vector tiles under the absolute URL `base`
/// (".../worlds/{id}"), with vector_layers (id, fields, minzoom, maxzoom); its tile URLs carry
/// the world's content `version` (`?v=`).
std::string vectorTileJson(const std::string& id, const std::string& base, double west,
                           double south, double east, double north, geometry::Vec2 center,
                           const std::string& version);

} // namespace strahler::app
