#pragma once

#include "ellipsoid.h"

#include "strahler/encoding/quantized_mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace strahler::encoding::qm {

/// One mesh vertex: its grid sample, height (m) and ECEF position.
struct Vertex {
  int column = 0;
  int row = 0;
  double height = 0.0;
  wgs84::Ecef position{};
};

/// A triangulated tile ready to write: vertices in order of first use by the triangles.
struct TileData {
  GeographicRect rect;                  ///< The tile, degrees.
  int samples = 0;                      ///< Grid samples per side (u, v quantise over them).
  std::vector<Vertex> vertices;         ///< Ordered by first use.
  std::vector<std::uint32_t> triangles; ///< Counter-clockwise vertex index triples.
  std::vector<std::uint8_t> normals;    ///< Two oct-encoded bytes per vertex, or empty.
};

/// The quantized-mesh-1.0 bytes of `tile` with the water mask and metadata of `options`.
std::string writeTile(const TileData& tile, const QuantizedMeshOptions& options);

} // namespace strahler::encoding::qm
