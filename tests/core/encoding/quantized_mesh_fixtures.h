#pragma once
// Test terrain and geodesy for the quantized-mesh tests, independent of the encoder: WGS84
// from its defining constants, height fields on a dyadic lattice of longitudes/latitudes (so
// neighbouring tiles see bit-identical shared samples), and a mesh analysis that maps decoded
// vertices back to grid samples.

#include "quantized_mesh_reader.h"

#include "strahler/encoding/quantized_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace strahler::encoding::test_support {

using Vec3 = std::array<double, 3>;

inline constexpr double kA = 6378137.0;
inline constexpr double kF = 1.0 / 298.257223563;
inline constexpr double kB = kA * (1.0 - kF);
inline constexpr double kE2 = 2.0 * kF - kF * kF;
inline constexpr double kRad = std::numbers::pi / 180.0;

inline double dot(const Vec3& p, const Vec3& q) {
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}
inline Vec3 sub(const Vec3& p, const Vec3& q) {
  return {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
}
inline Vec3 crossOf(const Vec3& p, const Vec3& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
inline double lengthOf(const Vec3& p) {
  return std::sqrt(dot(p, p));
}

/// Geodetic longitude/latitude (degrees) and height (m) to ECEF.
inline Vec3 geodeticToEcef(double lonDeg, double latDeg, double h) {
  const double lon = lonDeg * kRad, lat = latDeg * kRad;
  const double n = kA / std::sqrt(1.0 - kE2 * std::sin(lat) * std::sin(lat));
  return {(n + h) * std::cos(lat) * std::cos(lon), (n + h) * std::cos(lat) * std::sin(lon),
          (n * (1.0 - kE2) + h) * std::sin(lat)};
}

/// The geodetic up vector at longitude/latitude (degrees).
inline Vec3 upAt(double lonDeg, double latDeg) {
  const double lon = lonDeg * kRad, lat = latDeg * kRad;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

/// A height field on lattice points (I, J) at lon0 + I·step, lat0 + J·step (degrees).
struct Field {
  double lon0 = 10.0;
  double lat0 = 45.0;
  double step = 1.0 / 1024.0; // dyadic: every lattice longitude is exact in binary
  std::function<double(int, int)> height;
};

/// A deterministic value in [-1, 1] per lattice point.
inline double latticeNoise(int i, int j) {
  auto x = static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) * 0x9E3779B97F4A7C15ull ^
           static_cast<std::uint64_t>(static_cast<std::uint32_t>(j)) * 0xC2B2AE3D27D4EB4Full;
  x ^= x >> 29;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 32;
  return static_cast<double>(x % 2000001ull) / 1000000.0 - 1.0;
}

/// The tile of `samples` per side whose south-west sample is lattice (i0, j0), every
/// `stride`-th lattice point, with its one-sample border.
inline QuantizedMeshGrid gridFrom(const Field& field, int i0, int j0, int stride, int samples) {
  QuantizedMeshGrid grid;
  const int cells = samples - 1;
  grid.samples = samples;
  grid.rect = {field.lon0 + i0 * field.step, field.lat0 + j0 * field.step,
               field.lon0 + (i0 + cells * stride) * field.step,
               field.lat0 + (j0 + cells * stride) * field.step};
  for (int j = -1; j <= samples; ++j)
    for (int i = -1; i <= samples; ++i)
      grid.heights.push_back(field.height(i0 + i * stride, j0 + j * stride));
  return grid;
}

/// Sample (i, j) of a bordered grid.
inline double sampleOf(const QuantizedMeshGrid& grid, int i, int j) {
  const auto side = static_cast<std::size_t>(grid.samples + 2);
  return grid.heights[static_cast<std::size_t>(j + 1) * side + static_cast<std::size_t>(i + 1)];
}

/// The grid column/row of a quantized coordinate; throws unless it is one rounded exactly.
inline int gridIndexOf(int quantized, int cells) {
  const int k = static_cast<int>(std::lround(quantized * static_cast<double>(cells) / 32767.0));
  if (std::fabs(quantized - k * 32767.0 / cells) > 0.5)
    throw std::runtime_error("vertex is not on a grid sample");
  return k;
}

/// What a decoded tile says about its grid.
struct MeshAnalysis {
  std::vector<int> column, row;   ///< Grid sample of each vertex.
  double exactError = 0.0;        ///< Worst sample vs the mesh of exact vertex heights, m.
  double decodedError = 0.0;      ///< Worst sample vs the mesh of decoded heights, m.
  double worstVertexHeight = 0.0; ///< Worst decoded vertex height vs its sample, m.
  double area = 0.0;              ///< Sum of signed triangle areas, cells².
  std::size_t clockwise = 0;      ///< Triangles not counter-clockwise.
  std::size_t uncovered = 0;      ///< Samples in no triangle.
};

inline MeshAnalysis analyse(const DecodedTile& tile, const QuantizedMeshGrid& grid) {
  const int cells = grid.samples - 1;
  MeshAnalysis a;
  for (std::size_t k = 0; k < tile.vertexCount(); ++k) {
    a.column.push_back(gridIndexOf(tile.u[k], cells));
    a.row.push_back(gridIndexOf(tile.v[k], cells));
    a.worstVertexHeight = std::max(
        a.worstVertexHeight, std::fabs(tile.heightOf(k) - sampleOf(grid, a.column[k], a.row[k])));
  }
  std::vector<char> covered(static_cast<std::size_t>(grid.samples * grid.samples), 0);
  for (std::size_t t = 0; t < tile.indices.size(); t += 3) {
    const std::uint32_t p[3] = {tile.indices[t], tile.indices[t + 1], tile.indices[t + 2]};
    double x[3], y[3], exact[3], decoded[3];
    for (int c = 0; c < 3; ++c) {
      x[c] = a.column[p[c]];
      y[c] = a.row[p[c]];
      exact[c] = sampleOf(grid, a.column[p[c]], a.row[p[c]]);
      decoded[c] = tile.heightOf(p[c]);
    }
    const double twiceArea = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    a.area += 0.5 * twiceArea;
    if (!(twiceArea > 0.0)) {
      ++a.clockwise;
      continue;
    }
    const int x0 = static_cast<int>(std::min({x[0], x[1], x[2]}));
    const int x1 = static_cast<int>(std::max({x[0], x[1], x[2]}));
    const int y0 = static_cast<int>(std::min({y[0], y[1], y[2]}));
    const int y1 = static_cast<int>(std::max({y[0], y[1], y[2]}));
    for (int j = y0; j <= y1; ++j)
      for (int i = x0; i <= x1; ++i) {
        // Barycentric weights of (i, j).
        const double w1 = ((i - x[0]) * (y[2] - y[0]) - (j - y[0]) * (x[2] - x[0])) / twiceArea;
        const double w2 = ((x[1] - x[0]) * (j - y[0]) - (y[1] - y[0]) * (i - x[0])) / twiceArea;
        const double w0 = 1.0 - w1 - w2;
        if (w0 < -1e-12 || w1 < -1e-12 || w2 < -1e-12)
          continue;
        covered[static_cast<std::size_t>(j * grid.samples + i)] = 1;
        const double h = sampleOf(grid, i, j);
        a.exactError =
            std::max(a.exactError, std::fabs(w0 * exact[0] + w1 * exact[1] + w2 * exact[2] - h));
        a.decodedError = std::max(
            a.decodedError, std::fabs(w0 * decoded[0] + w1 * decoded[1] + w2 * decoded[2] - h));
      }
  }
  a.uncovered = static_cast<std::size_t>(std::count(covered.begin(), covered.end(), 0));
  return a;
}

/// Cesium's horizon-culling visibility test (EllipsoidalOccluder), all in scaled space.
inline bool occluded(const Vec3& point, const Vec3& camera) {
  const double vh2 = dot(camera, camera) - 1.0;
  const Vec3 vt = sub(point, camera);
  const double vtDotVc = -dot(vt, camera);
  return vh2 < 0 ? vtDotVc > 0 : vtDotVc > vh2 && vtDotVc * vtDotVc / dot(vt, vt) > vh2;
}

} // namespace strahler::encoding::test_support
