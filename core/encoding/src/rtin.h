#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace strahler::encoding::rtin {

/// A height grid to triangulate: samples × samples heights (samples = 2^k + 1), row-major, row
/// 0 south, with each sample's longitude and latitude (radians) for the curvature rule.
struct Grid {
  int samples = 0;
  std::span<const double> heights;    ///< samples² heights, m.
  std::span<const double> longitudes; ///< Per column, radians.
  std::span<const double> latitudes;  ///< Per row, radians.
};

/// What the mesh must satisfy.
struct Limits {
  double maxError = 0.0; ///< Largest vertical distance of a sample from its triangle, m.
  /// A triangle whose longest side spans more than this angle on the sphere is split, radians.
  double maxAngle = 0.0;
};

/// A right-triangulated irregular network over the grid.
struct Mesh {
  /// Three sample indices (row · samples + column) per triangle, counter-clockwise with
  /// columns east and rows north.
  std::vector<std::uint32_t> triangles;
  double maxError = 0.0; ///< Measured largest vertical distance of a sample from the mesh, m.
};

/// Triangulates the grid (martini's RTIN): every sample on the four edges is a vertex, and a
/// triangle is split while a sample inside it lies more than maxError from its plane, or its
/// longest side spans more than maxAngle; splits propagate so the mesh has no T-junctions.
Mesh triangulate(const Grid& grid, const Limits& limits);

} // namespace strahler::encoding::rtin
