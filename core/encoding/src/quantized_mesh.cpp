#include "strahler/encoding/quantized_mesh.h"

#include "ellipsoid.h"
#include "quantized_mesh_writer.h"
#include "rtin.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace strahler::encoding {
namespace {

using base::ErrorCode;
using wgs84::Ecef;

constexpr int kMaxSamples = 1025;
constexpr int kEllipsoidSamples = 17;
constexpr double kMaxAbsHeight = 1.0e6;
constexpr std::size_t kWaterMaskBytes = 256 * 256;
constexpr double kDegrees = std::numbers::pi / 180.0;

base::Error invalid(std::string message) {
  return base::makeError(ErrorCode::kInvalidInput, "quantized-mesh: " + std::move(message));
}

bool isGridSize(int samples) {
  if (samples < 3 || samples > kMaxSamples)
    return false;
  const int cells = samples - 1;
  return (cells & (cells - 1)) == 0;
}

base::Status validateRect(const GeographicRect& r) {
  if (!std::isfinite(r.west) || !std::isfinite(r.south) || !std::isfinite(r.east) ||
      !std::isfinite(r.north))
    return invalid("rectangle bounds must be finite");
  if (r.west < -180.0 || r.east > 180.0 || r.south < -90.0 || r.north > 90.0)
    return invalid("rectangle must lie within longitude [-180, 180] and latitude [-90, 90]");
  if (!(r.west < r.east))
    return invalid("rectangle west must be < east");
  if (!(r.south < r.north))
    return invalid("rectangle south must be < north");
  return base::Ok{};
}

base::Status validateOptions(const QuantizedMeshOptions& options) {
  if (std::isnan(options.maxError) || options.maxError < 0.0)
    return invalid("maxError must be >= 0");
  const std::size_t mask = options.waterMask.size();
  if (mask != 0 && mask != 1 && mask != kWaterMaskBytes)
    return invalid("water mask must have 0, 1 or 65536 bytes, not " + std::to_string(mask));
  if (options.metadata.size() > std::numeric_limits<std::uint32_t>::max() - 4)
    return invalid("metadata is too long");
  return base::Ok{};
}

base::Status validateGrid(const QuantizedMeshGrid& grid) {
  if (!isGridSize(grid.samples))
    return invalid("samples must be 2^k + 1 in [3, 1025], not " + std::to_string(grid.samples));
  const auto side = static_cast<std::size_t>(grid.samples) + 2;
  if (grid.heights.size() != side * side)
    return invalid("heights must hold (samples + 2)^2 = " + std::to_string(side * side) +
                   " values, not " + std::to_string(grid.heights.size()));
  for (std::size_t k = 0; k < grid.heights.size(); ++k) {
    if (!std::isfinite(grid.heights[k]))
      return invalid("height " + std::to_string(k) + " is not finite");
    // Far beyond any terrain; keeps the float32 header and the ECEF arithmetic exact enough.
    if (std::fabs(grid.heights[k]) > kMaxAbsHeight)
      return invalid("height " + std::to_string(k) + " is outside [-1e6, 1e6] m");
  }
  return validateRect(grid.rect);
}

/// Longitude/latitude of each column/row, radians; the ends exactly on the rectangle's edges
/// so that neighbours compute the same values for their shared samples.
std::vector<double> sampleAngles(double low, double high, int samples) {
  std::vector<double> angles(static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i) {
    const double degrees =
        i + 1 == samples ? high : low + i * (high - low) / static_cast<double>(samples - 1);
    angles[static_cast<std::size_t>(i)] = degrees * kDegrees;
  }
  return angles;
}

/// Cesium's AttributeCompression.octEncode (two bytes in 0..255) of a unit vector.
std::array<std::uint8_t, 2> octEncode(const Ecef& v) {
  const double sum = std::fabs(v[0]) + std::fabs(v[1]) + std::fabs(v[2]);
  double x = v[0] / sum, y = v[1] / sum;
  if (v[2] < 0.0) {
    const double ox = x, oy = y;
    x = (1.0 - std::fabs(oy)) * (ox < 0.0 ? -1.0 : 1.0);
    y = (1.0 - std::fabs(ox)) * (oy < 0.0 ? -1.0 : 1.0);
  }
  // toSNorm with JavaScript's Math.round (halves up).
  const auto snorm = [](double value) {
    const double clamped = std::clamp(value, -1.0, 1.0);
    return static_cast<std::uint8_t>(std::floor((clamped * 0.5 + 0.5) * 255.0 + 0.5));
  };
  return {snorm(x), snorm(y)};
}

/// The bordered grid without its border, for the mesher.
std::vector<double> innerHeights(const QuantizedMeshGrid& grid) {
  const auto n = static_cast<std::size_t>(grid.samples);
  std::vector<double> inner(n * n);
  for (std::size_t j = 0; j < n; ++j)
    std::copy_n(grid.heights.begin() + static_cast<std::ptrdiff_t>((j + 1) * (n + 2) + 1), n,
                inner.begin() + static_cast<std::ptrdiff_t>(j * n));
  return inner;
}

std::vector<wgs84::SinCos> sinCosOf(const std::vector<double>& angles) {
  std::vector<wgs84::SinCos> result;
  result.reserve(angles.size());
  for (double angle : angles)
    result.push_back(wgs84::SinCos::of(angle));
  return result;
}

/// Unit surface normals in ECEF from central differences over the bordered grid, in metres on
/// the ellipsoid (east spacing Δλ·N(φ)·cosφ, north spacing Δφ·M(φ)) in the local east-north-up
/// frame of the geodetic normal.
class NormalSampler {
public:
  NormalSampler(const QuantizedMeshGrid& grid, std::span<const wgs84::SinCos> longitudes,
                std::span<const wgs84::SinCos> latitudes)
      : grid_(grid), longitudes_(longitudes), latitudes_(latitudes) {
    const double cells = grid.samples - 1;
    const double dLon = (grid.rect.east - grid.rect.west) * kDegrees / cells;
    const double dLat = (grid.rect.north - grid.rect.south) * kDegrees / cells;
    for (const wgs84::SinCos& phi : latitudes) {
      eastSpan_.push_back(2.0 * dLon * wgs84::primeVerticalRadius(phi) * phi.cos);
      northSpan_.push_back(2.0 * dLat * wgs84::meridionalRadius(phi));
    }
  }

  Ecef operator()(int i, int j) const {
    const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
    // A pole's row is one point: it has no east-west slope.
    const double gx = eastSpan_[uj] > 1e-6 ? (at(i + 1, j) - at(i - 1, j)) / eastSpan_[uj] : 0.0;
    const double gy = (at(i, j + 1) - at(i, j - 1)) / northSpan_[uj];
    const double inv = 1.0 / std::sqrt(gx * gx + gy * gy + 1.0);
    const double e = -gx * inv, n = -gy * inv, u = inv;
    const double sl = longitudes_[ui].sin, cl = longitudes_[ui].cos;
    const double sp = latitudes_[uj].sin, cp = latitudes_[uj].cos;
    return {-sl * e - sp * cl * n + cp * cl * u, cl * e - sp * sl * n + cp * sl * u,
            cp * n + sp * u};
  }

private:
  double at(int i, int j) const {
    const auto side = static_cast<std::size_t>(grid_.samples) + 2;
    return grid_.heights[static_cast<std::size_t>(j + 1) * side + static_cast<std::size_t>(i + 1)];
  }

  const QuantizedMeshGrid& grid_;
  std::span<const wgs84::SinCos> longitudes_, latitudes_;
  std::vector<double> eastSpan_, northSpan_;
};

/// The mesh's vertices in order of first use by the triangles, so that the high-water-mark
/// index code applies.
struct OrderedMesh {
  std::vector<std::uint32_t> samples;   ///< Grid sample (row · samples + column) per vertex.
  std::vector<std::uint32_t> triangles; ///< Vertex indices.
};

OrderedMesh orderByFirstUse(const std::vector<std::uint32_t>& triangles, int samples) {
  constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> vertexOf(
      static_cast<std::size_t>(samples) * static_cast<std::size_t>(samples), kUnused);
  OrderedMesh ordered;
  ordered.triangles.reserve(triangles.size());
  for (std::uint32_t sample : triangles) {
    std::uint32_t& vertex = vertexOf[sample];
    if (vertex == kUnused) {
      vertex = static_cast<std::uint32_t>(ordered.samples.size());
      ordered.samples.push_back(sample);
    }
    ordered.triangles.push_back(vertex);
  }
  return ordered;
}

} // namespace

double cesiumLevelGeometricError(int level) noexcept {
  const double levelZero = wgs84::kSemiMajorAxis * 2.0 * std::numbers::pi * 0.25 / (65.0 * 2.0);
  return std::ldexp(levelZero, -level);
}

base::Result<std::string> encodeQuantizedMesh(const QuantizedMeshGrid& grid,
                                              const QuantizedMeshOptions& options,
                                              QuantizedMeshStats* stats) {
  if (auto valid = validateGrid(grid); !valid.ok())
    return std::move(valid).error();
  if (auto valid = validateOptions(options); !valid.ok())
    return std::move(valid).error();

  const int n = grid.samples;
  const std::vector<double> longitudes = sampleAngles(grid.rect.west, grid.rect.east, n);
  const std::vector<double> latitudes = sampleAngles(grid.rect.south, grid.rect.north, n);
  const std::vector<double> heights = innerHeights(grid);
  const rtin::Mesh rtinMesh = rtin::triangulate(
      {n, heights, longitudes, latitudes},
      {options.maxError, std::sqrt(8.0 * options.maxError / wgs84::kSemiMajorAxis)});
  OrderedMesh mesh = orderByFirstUse(rtinMesh.triangles, n);

  qm::TileData tile;
  tile.rect = grid.rect;
  tile.samples = n;
  tile.triangles = std::move(mesh.triangles);
  tile.vertices.reserve(mesh.samples.size());
  const std::vector<wgs84::SinCos> lonTrig = sinCosOf(longitudes), latTrig = sinCosOf(latitudes);
  const auto un = static_cast<std::uint32_t>(n);
  for (std::uint32_t s : mesh.samples) {
    const std::uint32_t i = s % un, j = s / un;
    const Ecef position = wgs84::toEcef(lonTrig[i], latTrig[j], heights[s]);
    tile.vertices.push_back({static_cast<int>(i), static_cast<int>(j), heights[s], position});
  }
  if (options.normals) {
    const NormalSampler normalAt(grid, lonTrig, latTrig);
    tile.normals.reserve(2 * tile.vertices.size());
    for (const qm::Vertex& v : tile.vertices) {
      const auto oct = octEncode(normalAt(v.column, v.row));
      tile.normals.push_back(oct[0]);
      tile.normals.push_back(oct[1]);
    }
  }
  if (stats != nullptr) {
    stats->vertices = tile.vertices.size();
    stats->triangles = tile.triangles.size() / 3;
    stats->maxError = rtinMesh.maxError;
  }
  return qm::writeTile(tile, options);
}

base::Result<std::string> encodeEllipsoidTile(const GeographicRect& rect,
                                              const QuantizedMeshOptions& options) {
  QuantizedMeshGrid grid;
  grid.rect = rect;
  grid.samples = kEllipsoidSamples;
  grid.heights.assign(static_cast<std::size_t>((kEllipsoidSamples + 2) * (kEllipsoidSamples + 2)),
                      0.0);
  return encodeQuantizedMesh(grid, options);
}

} // namespace strahler::encoding
