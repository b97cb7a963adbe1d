#pragma once

#include "strahler/base/result.h"
#include "strahler/geometry/vec2.h"

#include <cstdint>
#include <vector>

namespace strahler::encoding {

/// Largest n (quads per side) a mesh tile may have.
inline constexpr int kMaxMeshQuads = 1024;

/// What a mesh tile is built from: a regular grid of (n+1)×(n+1) vertices on the tile's
/// edges, plus a one-vertex border all round so normals match across tiles.
struct MeshGridInput {
  int quads = 64;        ///< n: quads per side, 1 ≤ n ≤ kMaxMeshQuads.
  geometry::Vec2 origin; ///< Local metres of vertex (0, 0): the tile's south-west corner.
  double spacing = 1.0;  ///< Metres between neighbouring vertices, > 0.
  /// (n+3)² finite heights, row 0 the southern border row (y = origin.y − spacing), column 0
  /// the western border column; the tile's own vertex (i, j) is at index (j+1)·(n+3) + (i+1).
  std::vector<float> heights;
  /// Metres the skirt hangs below the edge vertices, ≥ 0; 0 builds no skirt.
  double skirtDepth = 0.0;
  bool textureCoordinates = true; ///< Emit uv in [0, 1]² (u east, v south, as images go).
};

/// A triangle mesh in glTF's frame, relative to the tile's south-west corner:
/// x east, y up, z south (metres).
///
/// Vertex order: grid vertex (i, j) (i east, j north, 0 ≤ i, j ≤ n) is vertex j·(n+1) + i, at
/// (i·spacing, h, −j·spacing). With a skirt, vertex (n+1)² + k hangs below the k-th edge vertex
/// of the boundary walked counter-clockwise from (0, 0): south edge (k, 0) for k < n, east edge
/// (n, k−n), north edge (3n−k, n), west edge (0, 4n−k); each corner has one skirt vertex.
/// Triangles: 2n² grid triangles (quad by quad, row by row from the south), then 8n skirt
/// triangles facing outward, two per boundary edge in the same walk.
struct Mesh {
  std::vector<float> positions;       ///< xyz per vertex.
  std::vector<float> normals;         ///< Unit xyz per vertex.
  std::vector<float> uvs;             ///< uv per vertex (empty without texture coordinates).
  std::vector<std::uint32_t> indices; ///< Counter-clockwise seen from above (+y).
  geometry::Vec2 origin; ///< Local metres of the mesh origin (tile's south-west corner).
};

/// Builds the mesh of a grid tile: 2n² triangles, normals from central differences over the
/// bordered grid (so neighbouring tiles get bit-identical edge normals), and a skirt of
/// `skirtDepth` along the four edges. kInvalidInput when n, spacing, skirtDepth or the
/// heights break the invariants of MeshGridInput.
base::Result<Mesh> buildGridMesh(const MeshGridInput& input);

} // namespace strahler::encoding
