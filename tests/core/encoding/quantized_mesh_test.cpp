// quantized-mesh-1.0 tiles decoded by an independent reader (quantized_mesh_reader.h) and
// checked against the grid and WGS84 computed from its constants (quantized_mesh_fixtures.h).
#include "quantized_mesh_fixtures.h"
#include "quantized_mesh_reader.h"
#include "result_matchers.h"

#include "strahler/encoding/quantized_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace strahler::encoding {
namespace {

using test_support::analyse;
using test_support::DecodedTile;
using test_support::decodeQuantizedMesh;
using test_support::Field;
using test_support::gridFrom;
using test_support::Vec3;
namespace fs = std::filesystem;

constexpr int kSamples = 65;

Field flatField() {
  return {10.0, 45.0, 1.0 / 1024.0, [](int, int) { return 120.0; }};
}

Field tiltedField() {
  return {10.0, 45.0, 1.0 / 1024.0, [](int i, int j) { return 40.0 + 1.5 * i - 0.75 * j; }};
}

/// Hills plus ±25 m of per-sample noise: rough at any error below tens of metres.
Field roughField() {
  return {10.0, 45.0, 1.0 / 1024.0, [](int i, int j) {
            return 600.0 + 300.0 * std::sin(i / 23.0) * std::cos(j / 31.0) +
                   25.0 * test_support::latticeNoise(i, j);
          }};
}

Field coneField() {
  return {10.0, 45.0, 1.0 / 1024.0, [](int i, int j) {
            return std::max(0.0, 900.0 - 20.0 * std::hypot(i - 32.0, j - 32.0));
          }};
}

struct Encoded {
  std::string bytes;
  QuantizedMeshStats stats;
  DecodedTile tile;
};

Encoded encode(const QuantizedMeshGrid& grid, const QuantizedMeshOptions& options) {
  Encoded e;
  e.bytes = strahler::test_support::valueOf(encodeQuantizedMesh(grid, options, &e.stats));
  e.tile = decodeQuantizedMesh(e.bytes);
  return e;
}

QuantizedMeshOptions withError(double maxError) {
  QuantizedMeshOptions options;
  options.maxError = maxError;
  return options;
}

/// Longitude/latitude (degrees) of a decoded vertex's grid sample.
struct LonLat {
  double lon, lat;
};
LonLat lonLatOf(const QuantizedMeshGrid& grid, int column, int row) {
  const double cells = grid.samples - 1;
  const GeographicRect& r = grid.rect;
  return {r.west + column * (r.east - r.west) / cells, r.south + row * (r.north - r.south) / cells};
}

// --- Mesh ---------------------------------------------------------------------------------

void expectValidMesh(const Encoded& e, const QuantizedMeshGrid& grid, double maxError) {
  const auto a = analyse(e.tile, grid);
  const double cells = grid.samples - 1;
  const double quantum =
      (static_cast<double>(e.tile.maximumHeight) - e.tile.minimumHeight) / 32767.0;
  EXPECT_EQ(a.clockwise, 0u);
  EXPECT_EQ(a.uncovered, 0u);
  EXPECT_NEAR(a.area, cells * cells, 1e-9);
  EXPECT_LE(a.exactError, maxError + 1e-9);
  EXPECT_LE(a.decodedError, maxError + quantum + 1e-6);
  EXPECT_LE(a.worstVertexHeight, 0.5 * quantum + 1e-4);
  EXPECT_NEAR(e.stats.maxError, a.exactError, 1e-9) << "the stats must be the measured error";
  EXPECT_EQ(e.stats.vertices, e.tile.vertexCount());
  EXPECT_EQ(e.stats.triangles, e.tile.indices.size() / 3);
  EXPECT_EQ(e.tile.indexBytes, 2);
}

TEST(QuantizedMesh, FlatAndTiltedPlanesNeedOnlyTheEdgesAndTheirFan) {
  const Encoded flat = encode(gridFrom(flatField(), 0, 0, 1, kSamples), withError(1.0));
  const Encoded tilted = encode(gridFrom(tiltedField(), 0, 0, 1, kSamples), withError(1.0));
  expectValidMesh(flat, gridFrom(flatField(), 0, 0, 1, kSamples), 1.0);
  expectValidMesh(tilted, gridFrom(tiltedField(), 0, 0, 1, kSamples), 1.0);
  EXPECT_EQ(flat.stats.maxError, 0.0);
  EXPECT_LT(tilted.stats.maxError, 1e-9);
  EXPECT_EQ(flat.tile.vertexCount(), tilted.tile.vertexCount());
  EXPECT_LT(flat.tile.vertexCount(), 1000u) << "of 4225 samples";
  EXPECT_GE(flat.tile.vertexCount(), 256u) << "every edge sample is kept";
}

TEST(QuantizedMesh, RoughTerrainKeepsManySamplesWithinTheError) {
  const QuantizedMeshGrid grid = gridFrom(roughField(), 0, 0, 1, kSamples);
  const Encoded coarse = encode(grid, withError(20.0));
  const Encoded fine = encode(grid, withError(2.0));
  expectValidMesh(coarse, grid, 20.0);
  expectValidMesh(fine, grid, 2.0);
  EXPECT_GT(fine.tile.vertexCount(), 3000u);
  EXPECT_LT(coarse.tile.vertexCount(), fine.tile.vertexCount());
  EXPECT_GT(coarse.stats.maxError, 10.0) << "the error bound is used, not wasted";
}

TEST(QuantizedMesh, ConeStaysWithinTheError) {
  const QuantizedMeshGrid grid = gridFrom(coneField(), 0, 0, 1, kSamples);
  for (double maxError : {0.5, 5.0, 50.0, std::numeric_limits<double>::infinity()})
    expectValidMesh(encode(grid, withError(maxError)), grid, maxError);
}

TEST(QuantizedMesh, SmallestAndLargestGridsMesh) {
  for (int samples : {3, 1025}) {
    const QuantizedMeshGrid grid = gridFrom(coneField(), -samples / 2, -samples / 2, 1, samples);
    const Encoded e = encode(grid, withError(2.0));
    expectValidMesh(e, grid, 2.0);
    EXPECT_EQ(e.tile.south.size(), static_cast<std::size_t>(samples));
  }
}

TEST(QuantizedMesh, ZeroErrorKeepsEverySample) {
  const QuantizedMeshGrid grid = gridFrom(tiltedField(), 0, 0, 1, 17);
  const Encoded e = encode(grid, withError(0.0));
  EXPECT_EQ(e.tile.vertexCount(), 17u * 17u);
  EXPECT_EQ(e.tile.indices.size(), 3u * 2u * 16u * 16u);
  expectValidMesh(e, grid, 0.0);
}

TEST(QuantizedMesh, EdgeListsHoldExactlyTheGridsEdgeSamples) {
  const QuantizedMeshGrid grid = gridFrom(roughField(), 0, 0, 1, kSamples);
  const Encoded e = encode(grid, withError(20.0));
  const auto a = analyse(e.tile, grid);
  const int last = kSamples - 1;
  const auto expectEdge = [&](const std::vector<std::uint32_t>& list, auto onEdge,
                              const char* name) {
    std::vector<std::uint32_t> expected;
    for (std::uint32_t k = 0; k < e.tile.vertexCount(); ++k)
      if (onEdge(a.column[k], a.row[k]))
        expected.push_back(k);
    std::vector<std::uint32_t> sorted = list;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, expected) << name;
    EXPECT_EQ(list.size(), static_cast<std::size_t>(kSamples)) << name;
  };
  expectEdge(
      e.tile.west, [](int c, int) { return c == 0; }, "west");
  expectEdge(
      e.tile.south, [](int, int r) { return r == 0; }, "south");
  expectEdge(
      e.tile.east, [last](int c, int) { return c == last; }, "east");
  expectEdge(
      e.tile.north, [last](int, int r) { return r == last; }, "north");
  for (std::uint32_t k : e.tile.west)
    EXPECT_EQ(e.tile.u[k], 0);
  for (std::uint32_t k : e.tile.north)
    EXPECT_EQ(e.tile.v[k], 32767);
}

TEST(QuantizedMesh, ManyVerticesUseAlignedThirtyTwoBitIndices) {
  const QuantizedMeshGrid grid = gridFrom(roughField(), 0, 0, 1, 257);
  const Encoded e = encode(grid, withError(0.0));
  EXPECT_EQ(e.tile.vertexCount(), 257u * 257u);
  EXPECT_EQ(e.tile.indexBytes, 4);
  EXPECT_EQ(e.tile.triangleCountOffset % 4, 0u);
  // 88 + 4 + 6·66049 bytes of vertices end 2 bytes past a multiple of 4: 2 bytes of padding.
  EXPECT_EQ(e.tile.triangleCountOffset, 88u + 4u + 6u * 257u * 257u + 2u);
  EXPECT_EQ(e.tile.indices.size(), 3u * 2u * 256u * 256u);
  const auto a = analyse(e.tile, grid);
  EXPECT_EQ(a.clockwise, 0u);
  EXPECT_EQ(a.exactError, 0.0);
  EXPECT_EQ(e.tile.west.size(), 257u);
}

TEST(QuantizedMesh, UpToSixtyFourKiVerticesKeepSixteenBitIndices) {
  const QuantizedMeshGrid grid = gridFrom(roughField(), 0, 0, 1, 257);
  const Encoded e = encode(grid, withError(2.0));
  EXPECT_GT(e.tile.vertexCount(), 60000u);
  EXPECT_LE(e.tile.vertexCount(), 65536u);
  expectValidMesh(e, grid, 2.0);
}

TEST(QuantizedMesh, SameInputGivesSameBytes) {
  const QuantizedMeshGrid grid = gridFrom(roughField(), 3, 5, 1, kSamples);
  QuantizedMeshOptions options = withError(4.0);
  options.normals = true;
  EXPECT_EQ(strahler::test_support::valueOf(encodeQuantizedMesh(grid, options)),
            strahler::test_support::valueOf(encodeQuantizedMesh(grid, options)));
}

// --- Header -------------------------------------------------------------------------------

/// Cesium's horizon point magnitude for one scaled position, from the horizon-culling post.
double horizonMagnitude(const Vec3& scaled, const Vec3& direction) {
  const double length = std::max(1.0, test_support::lengthOf(scaled));
  const Vec3 unit{scaled[0] / test_support::lengthOf(scaled),
                  scaled[1] / test_support::lengthOf(scaled),
                  scaled[2] / test_support::lengthOf(scaled)};
  const double cosAlpha = test_support::dot(unit, direction);
  const double sinAlpha = test_support::lengthOf(test_support::crossOf(unit, direction));
  const double cosBeta = 1.0 / length;
  const double sinBeta = std::sqrt(length * length - 1.0) / length;
  return 1.0 / (cosAlpha * cosBeta - sinAlpha * sinBeta);
}

void expectHeaderMatchesGeodesy(const QuantizedMeshGrid& grid, double maxError) {
  const Encoded e = encode(grid, withError(maxError));
  const auto a = analyse(e.tile, grid);
  const DecodedTile& t = e.tile;
  std::vector<Vec3> positions;
  double low = 1e300, high = -1e300;
  for (std::size_t k = 0; k < t.vertexCount(); ++k) {
    const double h = test_support::sampleOf(grid, a.column[k], a.row[k]);
    const LonLat p = lonLatOf(grid, a.column[k], a.row[k]);
    positions.push_back(test_support::geodeticToEcef(p.lon, p.lat, h));
    low = std::min(low, h);
    high = std::max(high, h);
  }
  EXPECT_LE(t.minimumHeight, low);
  EXPECT_GT(t.minimumHeight, low - 1e-3);
  EXPECT_GE(t.maximumHeight, high);
  EXPECT_LT(t.maximumHeight, high + 1e-3);

  const GeographicRect& r = grid.rect;
  const Vec3 centre =
      test_support::geodeticToEcef(0.5 * (r.west + r.east), 0.5 * (r.south + r.north),
                                   0.5 * (static_cast<double>(t.minimumHeight) + t.maximumHeight));
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(t.center[c], centre[c], 1e-6);

  double diameter = 0.0;
  for (const Vec3& p : positions) {
    EXPECT_LE(test_support::lengthOf(test_support::sub(p, t.sphereCenter)), t.sphereRadius + 1e-7);
    diameter = std::max(diameter, test_support::lengthOf(test_support::sub(p, positions[0])));
  }
  EXPECT_LE(t.sphereRadius, diameter);

  // The horizon point: along the scaled sphere centre, as far as the worst vertex needs, in
  // the scaled space of the ellipsoid shrunk by a negative minimum height.
  const double shrink = std::min(0.0, static_cast<double>(t.minimumHeight));
  const Vec3 radii{test_support::kA + shrink, test_support::kA + shrink, test_support::kB + shrink};
  const auto scaled = [&](const Vec3& p) {
    return Vec3{p[0] / radii[0], p[1] / radii[1], p[2] / radii[2]};
  };
  Vec3 direction = scaled(t.sphereCenter);
  const double dl = test_support::lengthOf(direction);
  for (double& c : direction)
    c /= dl;
  double magnitude = 0.0;
  for (const Vec3& p : positions)
    magnitude = std::max(magnitude, horizonMagnitude(scaled(p), direction));
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(t.horizonOcclusionPoint[c], direction[c] * magnitude, 1e-9);

  // Sound: from any camera that cannot see the point, no vertex is visible either.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int hidden = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Vec3 camera{unit(random), unit(random), unit(random)};
    const double scale = (1.0005 + 0.5 * (unit(random) + 1.0)) / test_support::lengthOf(camera);
    for (double& c : camera)
      c *= scale;
    if (!test_support::occluded(t.horizonOcclusionPoint, camera))
      continue;
    ++hidden;
    for (const Vec3& p : positions)
      ASSERT_TRUE(test_support::occluded(scaled(p), camera)) << "culled a visible vertex";
  }
  EXPECT_GT(hidden, 500) << "the point should hide the tile from the far side";
}

TEST(QuantizedMesh, HeaderMatchesIndependentGeodesy) {
  expectHeaderMatchesGeodesy(gridFrom(roughField(), 0, 0, 1, kSamples), 5.0);
  expectHeaderMatchesGeodesy(gridFrom(coneField(), 0, 0, 1, kSamples), 1.0);
}

TEST(QuantizedMesh, HorizonPointHandlesTerrainBelowTheEllipsoid) {
  Field trench = roughField();
  trench.lat0 = -33.0;
  trench.height = [](int i, int j) { return -4000.0 + 30.0 * test_support::latticeNoise(i, j); };
  expectHeaderMatchesGeodesy(gridFrom(trench, 0, 0, 8, kSamples), 10.0);
  Field shore = roughField();
  shore.height = [](int i, int) { return 40.0 * i - 600.0; };
  expectHeaderMatchesGeodesy(gridFrom(shore, 0, 0, 1, kSamples), 1.0);
}

// --- Normals ------------------------------------------------------------------------------

/// Central differences over the bordered grid on the ellipsoid, rotated from east-north-up.
Vec3 expectedNormal(const QuantizedMeshGrid& grid, int i, int j) {
  const GeographicRect& r = grid.rect;
  const double cells = grid.samples - 1;
  const LonLat p = lonLatOf(grid, i, j);
  const double phi = p.lat * test_support::kRad, lambda = p.lon * test_support::kRad;
  const double w = 1.0 - test_support::kE2 * std::sin(phi) * std::sin(phi);
  const double n = test_support::kA / std::sqrt(w);
  const double m = test_support::kA * (1.0 - test_support::kE2) / (w * std::sqrt(w));
  const double dx = 2.0 * (r.east - r.west) / cells * test_support::kRad * n * std::cos(phi);
  const double dy = 2.0 * (r.north - r.south) / cells * test_support::kRad * m;
  const double gx =
      (test_support::sampleOf(grid, i + 1, j) - test_support::sampleOf(grid, i - 1, j)) / dx;
  const double gy =
      (test_support::sampleOf(grid, i, j + 1) - test_support::sampleOf(grid, i, j - 1)) / dy;
  const Vec3 east{-std::sin(lambda), std::cos(lambda), 0.0};
  const Vec3 north{-std::sin(phi) * std::cos(lambda), -std::sin(phi) * std::sin(lambda),
                   std::cos(phi)};
  const Vec3 up = test_support::upAt(p.lon, p.lat);
  Vec3 v;
  for (int c = 0; c < 3; ++c)
    v[c] = -gx * east[c] - gy * north[c] + up[c];
  const double l = test_support::lengthOf(v);
  return {v[0] / l, v[1] / l, v[2] / l};
}

/// Cesium's oct encoding, from AttributeCompression's description (snorm with rounding up).
std::array<int, 2> expectedOct(const Vec3& v) {
  const double s = std::fabs(v[0]) + std::fabs(v[1]) + std::fabs(v[2]);
  double x = v[0] / s, y = v[1] / s;
  if (v[2] < 0) {
    const double px = x;
    x = (1 - std::fabs(y)) * (px < 0 ? -1 : 1);
    y = (1 - std::fabs(px)) * (y < 0 ? -1 : 1);
  }
  return {static_cast<int>(std::floor((x * 0.5 + 0.5) * 255 + 0.5)),
          static_cast<int>(std::floor((y * 0.5 + 0.5) * 255 + 0.5))};
}

TEST(QuantizedMesh, NormalsFollowTheTerrainInOctEncoding) {
  for (const Field& field : {flatField(), roughField(), coneField()}) {
    const QuantizedMeshGrid grid = gridFrom(field, 0, 0, 1, kSamples);
    QuantizedMeshOptions options = withError(3.0);
    options.normals = true;
    const Encoded e = encode(grid, options);
    const auto a = analyse(e.tile, grid);
    const std::vector<std::uint8_t>& bytes = e.tile.extensions.at(1);
    ASSERT_EQ(bytes.size(), 2 * e.tile.vertexCount());
    std::size_t exact = 0;
    for (std::size_t k = 0; k < e.tile.vertexCount(); ++k) {
      const Vec3 expected = expectedNormal(grid, a.column[k], a.row[k]);
      const Vec3 decoded = test_support::octDecode(bytes[2 * k], bytes[2 * k + 1]);
      EXPECT_GT(test_support::dot(decoded, expected), std::cos(1.0 * test_support::kRad));
      const LonLat p = lonLatOf(grid, a.column[k], a.row[k]);
      EXPECT_GT(test_support::dot(decoded, test_support::upAt(p.lon, p.lat)), 0.2);
      const auto oct = expectedOct(expected);
      EXPECT_LE(std::abs(oct[0] - bytes[2 * k]), 1);
      EXPECT_LE(std::abs(oct[1] - bytes[2 * k + 1]), 1);
      exact += oct[0] == bytes[2 * k] && oct[1] == bytes[2 * k + 1];
    }
    EXPECT_GE(exact, e.tile.vertexCount() * 99 / 100);
  }
}

TEST(QuantizedMesh, OctDecodingRoundTripsUnitVectorsBelowAndAbove) {
  // Normals pointing into every octant: a tile at the antimeridian, south.
  Field steep = roughField();
  steep.lon0 = -179.5;
  steep.lat0 = -60.0;
  steep.height = [](int i, int j) { return 3000.0 * std::sin(i / 3.0) * std::cos(j / 4.0); };
  const QuantizedMeshGrid grid = gridFrom(steep, 0, 0, 1, 33);
  QuantizedMeshOptions options = withError(0.0);
  options.normals = true;
  const Encoded e = encode(grid, options);
  const auto a = analyse(e.tile, grid);
  const std::vector<std::uint8_t>& bytes = e.tile.extensions.at(1);
  for (std::size_t k = 0; k < e.tile.vertexCount(); ++k) {
    const Vec3 expected = expectedNormal(grid, a.column[k], a.row[k]);
    const Vec3 decoded = test_support::octDecode(bytes[2 * k], bytes[2 * k + 1]);
    EXPECT_NEAR(test_support::lengthOf(decoded), 1.0, 1e-12);
    EXPECT_GT(test_support::dot(decoded, expected), std::cos(1.0 * test_support::kRad));
  }
}

// --- Neighbours ---------------------------------------------------------------------------

struct EdgeVertex {
  int along; ///< Quantized position along the edge.
  double height;
  std::uint8_t octX, octY;
};

std::vector<EdgeVertex> edgeOf(const Encoded& e, const std::vector<std::uint32_t>& list,
                               bool vertical) {
  std::vector<EdgeVertex> edge;
  const std::vector<std::uint8_t>& normals = e.tile.extensions.at(1);
  for (std::uint32_t k : list)
    edge.push_back({vertical ? e.tile.v[k] : e.tile.u[k], e.tile.heightOf(k), normals[2 * k],
                    normals[2 * k + 1]});
  std::sort(edge.begin(), edge.end(),
            [](const EdgeVertex& p, const EdgeVertex& q) { return p.along < q.along; });
  return edge;
}

double quantumOf(const DecodedTile& t) {
  return (static_cast<double>(t.maximumHeight) - t.minimumHeight) / 32767.0;
}

TEST(QuantizedMesh, SameLevelNeighboursShareEdgeVerticesAndNormals) {
  QuantizedMeshOptions options = withError(8.0);
  options.normals = true;
  const Encoded west = encode(gridFrom(roughField(), 0, 0, 1, kSamples), options);
  const Encoded east = encode(gridFrom(roughField(), 64, 0, 1, kSamples), options);
  const Encoded north = encode(gridFrom(roughField(), 0, 64, 1, kSamples), options);
  const double slack = 0.5 * quantumOf(west.tile) + 0.5 * quantumOf(east.tile) + 1e-4;
  const auto compare = [&](const std::vector<EdgeVertex>& p, const std::vector<EdgeVertex>& q,
                           double heightSlack) {
    ASSERT_EQ(p.size(), q.size());
    for (std::size_t k = 0; k < p.size(); ++k) {
      EXPECT_EQ(p[k].along, q[k].along);
      EXPECT_NEAR(p[k].height, q[k].height, heightSlack);
      EXPECT_EQ(p[k].octX, q[k].octX);
      EXPECT_EQ(p[k].octY, q[k].octY);
    }
  };
  compare(edgeOf(west, west.tile.east, true), edgeOf(east, east.tile.west, true), slack);
  compare(edgeOf(west, west.tile.north, false), edgeOf(north, north.tile.south, false),
          0.5 * quantumOf(west.tile) + 0.5 * quantumOf(north.tile) + 1e-4);
}

TEST(QuantizedMesh, CoarserEdgeVerticesAreAmongTheFinerNeighbours) {
  // A tile of stride 2 and, east of it, the finer tile beside the south half of its east edge.
  const QuantizedMeshGrid coarseGrid = gridFrom(roughField(), 0, 0, 2, kSamples);
  const QuantizedMeshGrid fineGrid = gridFrom(roughField(), 128, 0, 1, kSamples);
  const Encoded coarse = encode(coarseGrid, withError(16.0));
  const Encoded fine = encode(fineGrid, withError(8.0));
  const auto a = analyse(coarse.tile, coarseGrid);
  const auto b = analyse(fine.tile, fineGrid);
  std::vector<double> fineLatitudes;
  for (std::uint32_t k : fine.tile.west)
    fineLatitudes.push_back(lonLatOf(fineGrid, b.column[k], b.row[k]).lat);
  int shared = 0;
  for (std::uint32_t k : coarse.tile.east) {
    const LonLat p = lonLatOf(coarseGrid, a.column[k], a.row[k]);
    if (p.lat > fineGrid.rect.north)
      continue;
    ++shared;
    EXPECT_NE(std::find(fineLatitudes.begin(), fineLatitudes.end(), p.lat), fineLatitudes.end())
        << "coarse edge vertex at latitude " << p.lat;
  }
  EXPECT_EQ(shared, 33);
}

// --- Extensions, the ellipsoid, errors ------------------------------------------------------

TEST(QuantizedMesh, ExtensionsComeInOrderWithTheirPayloads) {
  const QuantizedMeshGrid grid = gridFrom(coneField(), 0, 0, 1, kSamples);
  QuantizedMeshOptions options = withError(5.0);
  EXPECT_TRUE(encode(grid, options).tile.extensionOrder.empty());
  options.normals = true;
  options.waterMask.resize(256 * 256);
  for (std::size_t k = 0; k < options.waterMask.size(); ++k)
    options.waterMask[k] = static_cast<std::uint8_t>(k % 251);
  options.metadata = R"({"available":[[{"startX":0,"startY":0,"endX":1,"endY":1}]]})";
  const Encoded e = encode(grid, options);
  EXPECT_EQ(e.tile.extensionOrder, (std::vector<int>{1, 2, 4}));
  EXPECT_EQ(e.tile.extensions.at(1).size(), 2 * e.tile.vertexCount());
  EXPECT_EQ(e.tile.extensions.at(2), options.waterMask);
  const std::vector<std::uint8_t>& metadata = e.tile.extensions.at(4);
  ASSERT_EQ(metadata.size(), 4 + options.metadata.size());
  const std::uint32_t length = metadata[0] | metadata[1] << 8 | metadata[2] << 16 |
                               static_cast<std::uint32_t>(metadata[3]) << 24;
  EXPECT_EQ(length, options.metadata.size());
  EXPECT_EQ(std::string(metadata.begin() + 4, metadata.end()), options.metadata);

  options.normals = false;
  options.metadata.clear();
  options.waterMask = {255};
  const Encoded single = encode(grid, options);
  EXPECT_EQ(single.tile.extensionOrder, (std::vector<int>{2}));
  EXPECT_EQ(single.tile.extensions.at(2), (std::vector<std::uint8_t>{255}));
}

TEST(QuantizedMesh, LevelErrorIsCesiumsHeightmapEstimate) {
  EXPECT_NEAR(cesiumLevelGeometricError(0), 77067.34, 0.01);
  EXPECT_NEAR(cesiumLevelGeometricError(12), 77067.34 / 4096.0, 1e-5);
  EXPECT_DOUBLE_EQ(cesiumLevelGeometricError(5) / 2.0, cesiumLevelGeometricError(6));
}

TEST(QuantizedMesh, EllipsoidTilesAreSeaLevelAndFollowTheCurvature) {
  for (int level : {0, 3, 9}) {
    const double size = 180.0 / (1 << level);
    const GeographicRect rect{-180.0 + size, 90.0 - size, -180.0 + 2 * size, 90.0};
    QuantizedMeshOptions options = withError(cesiumLevelGeometricError(level));
    options.normals = true;
    options.waterMask = {255};
    const std::string bytes = strahler::test_support::valueOf(encodeEllipsoidTile(rect, options));
    const DecodedTile t = decodeQuantizedMesh(bytes);
    EXPECT_EQ(t.minimumHeight, 0.0f);
    EXPECT_EQ(t.maximumHeight, 0.0f);
    for (double c : t.horizonOcclusionPoint)
      EXPECT_TRUE(std::isfinite(c));
    EXPECT_EQ(t.west.size(), 17u);
    EXPECT_EQ(t.extensionOrder, (std::vector<int>{1, 2}));
    // No triangle side longer than the curvature allows, unless it is one grid cell's.
    const double limit = std::sqrt(8.0 * options.maxError / test_support::kA);
    for (std::size_t k = 0; k < t.indices.size(); k += 3)
      for (int s = 0; s < 3; ++s) {
        const std::uint32_t p = t.indices[k + s], q = t.indices[k + (s + 1) % 3];
        const auto at = [&](std::uint32_t v) {
          return test_support::upAt(rect.west + t.u[v] / 32767.0 * size,
                                    rect.south + t.v[v] / 32767.0 * size);
        };
        const double angle = std::acos(std::clamp(test_support::dot(at(p), at(q)), -1.0, 1.0));
        const bool oneCell =
            std::abs(t.u[p] - t.u[q]) <= 2048 + 1 && std::abs(t.v[p] - t.v[q]) <= 2048 + 1;
        EXPECT_TRUE(angle <= limit * 1.01 || oneCell) << "level " << level;
      }
  }
}

TEST(QuantizedMesh, MalformedInputIsRejected) {
  const QuantizedMeshGrid good = gridFrom(flatField(), 0, 0, 1, 17);
  const QuantizedMeshOptions options = withError(1.0);
  STRAHLER_ASSERT_OK(encodeQuantizedMesh(good, options));
  const auto rejects = [&](QuantizedMeshGrid grid, QuantizedMeshOptions o, const char* part) {
    EXPECT_TRUE(strahler::test_support::failsWith(encodeQuantizedMesh(grid, o),
                                                  base::ErrorCode::kInvalidInput, part));
  };
  for (int samples : {0, 2, 16, 18, 2049}) {
    QuantizedMeshGrid grid = good;
    grid.samples = samples;
    rejects(grid, options, "samples must be 2^k + 1");
  }
  QuantizedMeshGrid grid = good;
  grid.heights.pop_back();
  rejects(grid, options, "heights must hold");
  grid = good;
  grid.heights[40] = std::numeric_limits<double>::quiet_NaN();
  rejects(grid, options, "height 40 is not finite");
  grid = good;
  grid.heights[3] = std::numeric_limits<double>::infinity();
  rejects(grid, options, "height 3 is not finite");
  grid = good;
  grid.heights[7] = -2.0e6;
  rejects(grid, options, "height 7 is outside [-1e6, 1e6] m");
  grid = good;
  grid.rect.east = grid.rect.west;
  rejects(grid, options, "west must be < east");
  grid = good;
  grid.rect.north = grid.rect.south - 1.0;
  rejects(grid, options, "south must be < north");
  grid = good;
  grid.rect.east = 180.5;
  rejects(grid, options, "within longitude");
  grid = good;
  grid.rect.south = -91.0;
  rejects(grid, options, "within longitude");
  grid = good;
  grid.rect.north = std::numeric_limits<double>::quiet_NaN();
  rejects(grid, options, "finite");
  rejects(good, withError(-1.0), "maxError");
  rejects(good, withError(std::numeric_limits<double>::quiet_NaN()), "maxError");
  QuantizedMeshOptions mask = options;
  mask.waterMask.resize(2);
  rejects(good, mask, "water mask must have 0, 1 or 65536 bytes, not 2");
  EXPECT_TRUE(strahler::test_support::failsWith(encodeEllipsoidTile({10, 10, 5, 20}, options),
                                                base::ErrorCode::kInvalidInput,
                                                "west must be < east"));
}

// --- Golden tile ----------------------------------------------------------------------------
// tests/data/golden/quantized_mesh_17.terrain; STRAHLER_UPDATE_GOLDEN=1 rewrites it.

TEST(QuantizedMeshGolden, MatchesTheCommittedTileByteForByte) {
  // Heights from integer arithmetic only, so the input is the same everywhere.
  Field field = flatField();
  field.height = [](int i, int j) {
    return static_cast<double>(((i + 40) * 7919 + (j + 40) * 104729) % 2003) * 0.25 - 100.0;
  };
  QuantizedMeshOptions options = withError(40.0);
  options.normals = true;
  options.waterMask = {0};
  options.metadata = R"({"available":[[{"startX":0,"startY":0,"endX":1,"endY":0}]]})";
  const std::string bytes =
      strahler::test_support::valueOf(encodeQuantizedMesh(gridFrom(field, 0, 0, 1, 17), options));
  const fs::path path = fs::path(STRAHLER_TEST_DATA_DIR) / "golden" / "quantized_mesh_17.terrain";
  const char* update = std::getenv("STRAHLER_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
    return;
  }
  ASSERT_TRUE(fs::exists(path)) << path << " is missing: run with STRAHLER_UPDATE_GOLDEN=1";
  std::ifstream in(path, std::ios::binary);
  const std::string committed{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_TRUE(committed == bytes)
      << path << " differs from today's encoding; if the change is intended, rerun with "
      << "STRAHLER_UPDATE_GOLDEN=1 and review the new file";
  EXPECT_NO_THROW(decodeQuantizedMesh(committed));
}

} // namespace
} // namespace strahler::encoding
