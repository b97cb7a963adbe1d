#include "result_matchers.h"
#include "synthetic_terrain.h"

#include "strahler/encoding/mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace strahler::encoding {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 position(const Mesh& mesh, std::size_t v) {
  return {mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]};
}

Vec3 normal(const Mesh& mesh, std::size_t v) {
  return {mesh.normals[3 * v], mesh.normals[3 * v + 1], mesh.normals[3 * v + 2]};
}

Vec3 minus(Vec3 a, Vec3 b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

Vec3 cross(Vec3 a, Vec3 b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec3 faceNormal(const Mesh& mesh, std::size_t face) {
  const Vec3 a = position(mesh, mesh.indices[3 * face]);
  const Vec3 b = position(mesh, mesh.indices[3 * face + 1]);
  const Vec3 c = position(mesh, mesh.indices[3 * face + 2]);
  return cross(minus(b, a), minus(c, a));
}

/// A tile whose bordered heights come from h(east, north) in local metres.
MeshGridInput tileFrom(int quads, double spacing, geometry::Vec2 origin, double skirtDepth,
                       const std::function<float(double, double)>& h) {
  MeshGridInput input;
  input.quads = quads;
  input.spacing = spacing;
  input.origin = origin;
  input.skirtDepth = skirtDepth;
  for (int j = -1; j <= quads + 1; ++j)
    for (int i = -1; i <= quads + 1; ++i)
      input.heights.push_back(h(origin.x + i * spacing, origin.y + j * spacing));
  return input;
}

Mesh build(const MeshGridInput& input) {
  auto mesh = buildGridMesh(input);
  EXPECT_TRUE(mesh.ok()) << (mesh.ok() ? "" : mesh.error().message);
  return mesh.ok() ? std::move(mesh).value() : Mesh{};
}

std::size_t vertexCount(const Mesh& mesh) {
  return mesh.positions.size() / 3;
}

TEST(GridMesh, HasGridVerticesAndTrianglesWithoutSkirt) {
  const Mesh mesh = build(test_support::syntheticTile(8, 10.0, {}, 0.0, true));
  EXPECT_EQ(vertexCount(mesh), 81u);
  EXPECT_EQ(mesh.normals.size(), 3u * 81u);
  EXPECT_EQ(mesh.uvs.size(), 2u * 81u);
  EXPECT_EQ(mesh.indices.size(), 3u * 2u * 64u);
}

TEST(GridMesh, SkirtAddsOneVertexPerEdgeVertexAndTwoTrianglesPerEdge) {
  const Mesh mesh = build(test_support::syntheticTile(8, 10.0, {}, 25.0, true));
  EXPECT_EQ(vertexCount(mesh), 81u + 32u);
  EXPECT_EQ(mesh.indices.size(), 3u * (2u * 64u + 8u * 8u));
  for (std::uint32_t index : mesh.indices)
    ASSERT_LT(index, vertexCount(mesh));
}

TEST(GridMesh, VertexOrderIsRowMajorFromTheSouthWest) {
  const geometry::Vec2 origin{1000.0, 2000.0};
  const MeshGridInput input = test_support::syntheticTile(4, 12.5, origin, 0.0, false);
  const Mesh mesh = build(input);
  for (int j = 0; j <= 4; ++j) {
    for (int i = 0; i <= 4; ++i) {
      const Vec3 p = position(mesh, static_cast<std::size_t>(j * 5 + i));
      EXPECT_EQ(p[0], i * 12.5);
      EXPECT_EQ(p[2], -j * 12.5);
      EXPECT_EQ(p[1], input.heights[static_cast<std::size_t>((j + 1) * 7 + i + 1)]);
    }
  }
  EXPECT_EQ(mesh.origin, origin);
}

TEST(GridMesh, GridTrianglesAreCounterClockwiseSeenFromAbove) {
  const Mesh mesh = build(test_support::syntheticTile(16, 5.0, {300.0, -700.0}, 0.0, false));
  for (std::size_t f = 0; f < mesh.indices.size() / 3; ++f)
    ASSERT_GT(faceNormal(mesh, f)[1], 0.0) << "face " << f;
}

TEST(GridMesh, SkirtHangsBelowEdgeVerticesAndFacesOutward) {
  const int n = 6;
  const double spacing = 10.0, depth = 40.0;
  const Mesh mesh = build(test_support::syntheticTile(n, spacing, {}, depth, true));
  const std::size_t grid = (n + 1) * (n + 1);
  for (std::size_t f = 2 * n * n; f < mesh.indices.size() / 3; ++f) {
    const Vec3 normalOfFace = faceNormal(mesh, f);
    const Vec3 a = position(mesh, mesh.indices[3 * f]);
    const Vec3 fromCentre = {a[0] - n * spacing / 2, 0.0, a[2] + n * spacing / 2};
    EXPECT_NEAR(normalOfFace[1], 0.0, 1e-9) << "skirt face " << f << " is vertical";
    EXPECT_GT(normalOfFace[0] * fromCentre[0] + normalOfFace[2] * fromCentre[2], 0.0)
        << "skirt face " << f << " faces outward";
  }
  for (std::size_t v = grid; v < vertexCount(mesh); ++v) {
    const Vec3 low = position(mesh, v);
    std::size_t top = grid;
    for (std::size_t g = 0; g < grid; ++g)
      if (position(mesh, g)[0] == low[0] && position(mesh, g)[2] == low[2])
        top = g;
    ASSERT_LT(top, grid) << "skirt vertex " << v << " has an edge vertex above it";
    EXPECT_FLOAT_EQ(static_cast<float>(position(mesh, top)[1] - low[1]), float(depth));
    EXPECT_EQ(normal(mesh, top), normal(mesh, v));
    EXPECT_EQ(mesh.uvs[2 * top], mesh.uvs[2 * v]);
    EXPECT_EQ(mesh.uvs[2 * top + 1], mesh.uvs[2 * v + 1]);
  }
}

TEST(GridMesh, NormalsOfATiltedPlaneAreExact) {
  // Heights are multiples of 0.25 m: exact in float, so central differences are exact too.
  const auto plane = [](double east, double north) {
    return static_cast<float>(100.0 + 0.5 * east - 0.25 * north);
  };
  const Mesh mesh = build(tileFrom(8, 2.0, {64.0, -32.0}, 10.0, plane));
  const double length = std::sqrt(0.5 * 0.5 + 1.0 + 0.25 * 0.25);
  // y = 0.5 x − 0.25 north = 0.5 x + 0.25 z: normal ∝ (−0.5, 1, −0.25).
  for (std::size_t v = 0; v < vertexCount(mesh); ++v) {
    const Vec3 n = normal(mesh, v);
    EXPECT_FLOAT_EQ(float(n[0]), float(-0.5 / length)) << v;
    EXPECT_FLOAT_EQ(float(n[1]), float(1.0 / length)) << v;
    EXPECT_FLOAT_EQ(float(n[2]), float(-0.25 / length)) << v;
  }
}

TEST(GridMesh, NormalsAreUnitAndPointUp) {
  const Mesh mesh = build(test_support::syntheticTile(32, 30.0, {5000.0, 1000.0}, 50.0, false));
  for (std::size_t v = 0; v < vertexCount(mesh); ++v) {
    const Vec3 n = normal(mesh, v);
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-6);
    EXPECT_GT(n[1], 0.0);
  }
}

TEST(GridMesh, TextureCoordinatesSpanTheUnitSquareWithVSouth) {
  const int n = 8;
  const Mesh mesh = build(test_support::syntheticTile(n, 10.0, {}, 5.0, true));
  for (float value : mesh.uvs) {
    EXPECT_GE(value, 0.0f);
    EXPECT_LE(value, 1.0f);
  }
  const auto uv = [&](int i, int j) {
    const std::size_t v = static_cast<std::size_t>(j * (n + 1) + i);
    return std::array<float, 2>{mesh.uvs[2 * v], mesh.uvs[2 * v + 1]};
  };
  EXPECT_EQ(uv(0, 0), (std::array<float, 2>{0.0f, 1.0f})); // south-west: image bottom left
  EXPECT_EQ(uv(n, n), (std::array<float, 2>{1.0f, 0.0f})); // north-east: image top right
  EXPECT_EQ(uv(n / 2, n / 4), (std::array<float, 2>{0.5f, 0.75f}));
}

TEST(GridMesh, NoTextureCoordinatesWhenNotRequested) {
  const Mesh mesh = build(test_support::syntheticTile(4, 10.0, {}, 5.0, false));
  EXPECT_TRUE(mesh.uvs.empty());
}

/// World (east, up, north) of vertex v: the mesh origin plus its glTF position.
Vec3 world(const Mesh& mesh, std::size_t v) {
  const Vec3 p = position(mesh, v);
  return {mesh.origin.x + p[0], p[1], mesh.origin.y - p[2]};
}

/// Cuts the bordered input of tile (tx, ty) out of one (2n+3)² field.
MeshGridInput cut(const std::vector<float>& field, int n, double spacing, geometry::Vec2 origin,
                  int tx, int ty) {
  MeshGridInput input;
  input.quads = n;
  input.spacing = spacing;
  input.skirtDepth = 20.0;
  input.origin = {origin.x + tx * n * spacing, origin.y + ty * n * spacing};
  const int fieldSide = 2 * n + 3;
  for (int j = 0; j < n + 3; ++j)
    for (int i = 0; i < n + 3; ++i)
      input.heights.push_back(
          field[static_cast<std::size_t>((ty * n + j) * fieldSide + tx * n + i)]);
  return input;
}

TEST(GridMesh, NeighbouringTilesShareEdgeVerticesAndNormalsBitForBit) {
  const int n = 16;
  const double spacing = 30.0;
  const geometry::Vec2 origin{123456.0, -98304.0};
  std::vector<float> field;
  for (int j = -1; j <= 2 * n + 1; ++j)
    for (int i = -1; i <= 2 * n + 1; ++i)
      field.push_back(
          test_support::syntheticHeight(origin.x + i * spacing + 0.37, origin.y + j * spacing));
  const Mesh west = build(cut(field, n, spacing, origin, 0, 0));
  const Mesh east = build(cut(field, n, spacing, origin, 1, 0));
  const Mesh north = build(cut(field, n, spacing, origin, 0, 1));
  for (int k = 0; k <= n; ++k) {
    const auto at = [n](int i, int j) { return static_cast<std::size_t>(j * (n + 1) + i); };
    EXPECT_EQ(world(west, at(n, k)), world(east, at(0, k))) << "east edge " << k;
    EXPECT_EQ(normal(west, at(n, k)), normal(east, at(0, k))) << "east edge " << k;
    EXPECT_EQ(world(west, at(k, n)), world(north, at(k, 0))) << "north edge " << k;
    EXPECT_EQ(normal(west, at(k, n)), normal(north, at(k, 0))) << "north edge " << k;
  }
}

TEST(GridMesh, RejectsInvalidInput) {
  const MeshGridInput good = test_support::syntheticTile(4, 10.0, {}, 5.0, true);
  STRAHLER_ASSERT_OK(buildGridMesh(good));
  std::vector<MeshGridInput> bad(9, good);
  bad[0].quads = 0;
  bad[1].quads = kMaxMeshQuads + 1;
  bad[2].heights.pop_back();
  bad[3].spacing = 0.0;
  bad[4].spacing = std::numeric_limits<double>::quiet_NaN();
  bad[5].heights[10] = std::numeric_limits<float>::quiet_NaN();
  bad[6].heights[0] = std::numeric_limits<float>::infinity();
  bad[7].skirtDepth = -1.0;
  bad[8].origin.x = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < bad.size(); ++k) {
    const auto mesh = buildGridMesh(bad[k]);
    ASSERT_FALSE(mesh.ok()) << "case " << k;
    EXPECT_EQ(mesh.error().code, base::ErrorCode::kInvalidInput) << "case " << k;
    EXPECT_FALSE(mesh.error().message.empty());
  }
}

} // namespace
} // namespace strahler::encoding
