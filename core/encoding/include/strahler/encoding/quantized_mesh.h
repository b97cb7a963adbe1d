#pragma once

#include "strahler/base/result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace strahler::encoding {

/// A rectangle of longitude and latitude on the WGS84 ellipsoid, degrees.
struct GeographicRect {
  double west = 0.0;  ///< Longitude of the west edge.
  double south = 0.0; ///< Latitude of the south edge.
  double east = 0.0;  ///< Longitude of the east edge.
  double north = 0.0; ///< Latitude of the north edge.
};

/// The heights of one terrain tile, sampled on a regular longitude/latitude grid.
struct QuantizedMeshGrid {
  GeographicRect rect; ///< The tile.
  /// Vertices per side, edge-inclusive: 2^k + 1 (k in 1..10). Sample (i, j) is at longitude
  /// west + i·(east − west)/(samples − 1), latitude south + j·(north − south)/(samples − 1).
  int samples = 0;
  /// Heights above the ellipsoid, m: (samples + 2)² values, row-major, row 0 south, with a
  /// one-sample border outside the tile (for normals that agree with the neighbours'):
  /// heights[(j + 1)·(samples + 2) + (i + 1)] is sample (i, j).
  std::vector<double> heights;
};

/// What a quantized-mesh tile carries beyond its mesh.
struct QuantizedMeshOptions {
  /// Largest vertical distance (m) between the mesh and any grid sample, before the heights'
  /// 16-bit quantisation (which adds up to (max − min) / 65,534); 0 keeps every sample.
  /// The ellipsoid's curvature counts too: a triangle whose longest side spans more than
  /// √(8 · maxError / 6,378,137 m) radians (its chord would sag more than maxError below the
  /// surface) is split, so large flat tiles of the top levels still follow the globe.
  double maxError = 0.0;
  bool normals = false; ///< Add the octvertexnormals extension (id 1).
  /// The watermask extension (id 2): empty for none; 1 byte (0 all land, 255 all water) or
  /// 256·256 bytes, row 0 north, column 0 west, 0 land … 255 water.
  std::vector<std::uint8_t> waterMask;
  std::string metadata; ///< The metadata extension's JSON (id 4); empty for none.
};

/// What the mesher made of a grid (for tests and benchmarks).
struct QuantizedMeshStats {
  std::size_t vertices = 0;  ///< Vertices written.
  std::size_t triangles = 0; ///< Triangles written.
  double maxError = 0.0;     ///< Largest vertical distance of a grid sample from the mesh, m.
};

/// Cesium's geometric error of a tile at `level` of the geographic (2 × 1 roots) pyramid, m:
/// the equator's quarter over 65 samples and 2 root tiles (≈ 77 km at level 0), halved per level.
double cesiumLevelGeometricError(int level) noexcept;

/// Encodes a quantized-mesh-1.0 tile: the 88-byte header (centre, bounding sphere and horizon
/// occlusion point in ECEF on WGS84, min/max height), an adaptive triangulation of the grid
/// (right-triangulated irregular network: every triangle kept whose samples lie within
/// `maxError` of it) that keeps every sample on the tile's four edges, so that neighbours of
/// one level share their edge vertices exactly; zig-zag delta u/v/height, high-water-mark
/// indices (32-bit above 65,536 vertices), counter-clockwise triangles, edge index lists, and
/// the extensions asked for. kInvalidInput for a malformed grid or options.
base::Result<std::string> encodeQuantizedMesh(const QuantizedMeshGrid& grid,
                                              const QuantizedMeshOptions& options,
                                              QuantizedMeshStats* stats = nullptr);

/// The tile Cesium expects where there is no terrain: the ellipsoid (height 0) over `rect`,
/// meshed like encodeQuantizedMesh() would mesh a grid of zeros (so curved within maxError),
/// with the extensions of `options`.
base::Result<std::string> encodeEllipsoidTile(const GeographicRect& rect,
                                              const QuantizedMeshOptions& options);

} // namespace strahler::encoding
