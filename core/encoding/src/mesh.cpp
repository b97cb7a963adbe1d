#include "strahler/encoding/mesh.h"

#include <cmath>
#include <cstddef>
#include <string>

namespace strahler::encoding {
namespace {

using base::ErrorCode;

/// Index arithmetic of one tile: n quads per side, (n+1)² grid vertices, (n+3)² heights.
struct GridShape {
  int n;
  std::size_t side() const { return static_cast<std::size_t>(n) + 1; }
  std::size_t gridVertices() const { return side() * side(); }
  std::uint32_t vertex(int i, int j) const {
    return static_cast<std::uint32_t>(static_cast<std::size_t>(j) * side() +
                                      static_cast<std::size_t>(i));
  }
  std::size_t height(int i, int j) const {
    return static_cast<std::size_t>(j + 1) * (side() + 2) + static_cast<std::size_t>(i + 1);
  }
};

base::Status validate(const MeshGridInput& input) {
  if (input.quads < 1 || input.quads > kMaxMeshQuads)
    return base::makeError(ErrorCode::kInvalidInput, "mesh quads per side must be in [1, " +
                                                         std::to_string(kMaxMeshQuads) + "], got " +
                                                         std::to_string(input.quads));
  if (!(input.spacing > 0.0) || !std::isfinite(input.spacing))
    return base::makeError(ErrorCode::kInvalidInput, "mesh spacing must be finite and > 0");
  if (!(input.skirtDepth >= 0.0) || !std::isfinite(input.skirtDepth))
    return base::makeError(ErrorCode::kInvalidInput, "mesh skirt depth must be finite and >= 0");
  const std::size_t bordered = GridShape{input.quads}.side() + 2;
  if (input.heights.size() != bordered * bordered)
    return base::makeError(ErrorCode::kInvalidInput,
                           "mesh heights: expected " + std::to_string(bordered * bordered) +
                               " values ((n+3)^2), got " + std::to_string(input.heights.size()));
  for (std::size_t k = 0; k < input.heights.size(); ++k)
    if (!std::isfinite(input.heights[k]))
      return base::makeError(ErrorCode::kInvalidInput,
                             "mesh heights: value " + std::to_string(k) + " is not finite");
  if (!std::isfinite(input.origin.x) || !std::isfinite(input.origin.y))
    return base::makeError(ErrorCode::kInvalidInput, "mesh origin must be finite");
  return base::Ok{};
}

/// Unit normal of y = h(x, z) from central differences; only (i, j)'s four neighbours
/// enter, in a fixed order, so any tile sharing them computes the same bits.
void appendNormal(const MeshGridInput& input, GridShape shape, int i, int j,
                  std::vector<float>& out) {
  const auto& h = input.heights;
  const double twoSpacing = 2.0 * input.spacing;
  const double east =
      (double{h[shape.height(i + 1, j)]} - double{h[shape.height(i - 1, j)]}) / twoSpacing;
  const double north =
      (double{h[shape.height(i, j + 1)]} - double{h[shape.height(i, j - 1)]}) / twoSpacing;
  // Surface (x, h, z) with z = −north: normal ∝ (−∂h/∂x, 1, −∂h/∂z) = (−east, 1, north).
  const double length = std::sqrt(east * east + 1.0 + north * north);
  out.push_back(static_cast<float>(-east / length));
  out.push_back(static_cast<float>(1.0 / length));
  out.push_back(static_cast<float>(north / length));
}

void appendGridVertices(const MeshGridInput& input, GridShape shape, Mesh& mesh) {
  const double n = static_cast<double>(input.quads);
  for (int j = 0; j <= input.quads; ++j) {
    const float z = -static_cast<float>(j * input.spacing);
    for (int i = 0; i <= input.quads; ++i) {
      mesh.positions.push_back(static_cast<float>(i * input.spacing));
      mesh.positions.push_back(input.heights[shape.height(i, j)]);
      mesh.positions.push_back(z);
      appendNormal(input, shape, i, j, mesh.normals);
      if (input.textureCoordinates) {
        mesh.uvs.push_back(static_cast<float>(i / n));
        mesh.uvs.push_back(static_cast<float>(1.0 - j / n));
      }
    }
  }
}

void appendGridTriangles(GridShape shape, std::vector<std::uint32_t>& indices) {
  for (int j = 0; j < shape.n; ++j) {
    for (int i = 0; i < shape.n; ++i) {
      const std::uint32_t sw = shape.vertex(i, j), se = shape.vertex(i + 1, j);
      const std::uint32_t ne = shape.vertex(i + 1, j + 1), nw = shape.vertex(i, j + 1);
      // East then north is counter-clockwise seen from +y (z points south).
      indices.insert(indices.end(), {sw, se, ne, sw, ne, nw});
    }
  }
}

/// Grid vertex of the k-th step of the counter-clockwise boundary walk from (0, 0).
std::uint32_t boundaryVertex(GridShape shape, int k) {
  const int n = shape.n;
  if (k < n)
    return shape.vertex(k, 0);
  if (k < 2 * n)
    return shape.vertex(n, k - n);
  if (k < 3 * n)
    return shape.vertex(3 * n - k, n);
  return shape.vertex(0, 4 * n - k);
}

void appendSkirt(const MeshGridInput& input, GridShape shape, Mesh& mesh) {
  const int count = 4 * shape.n;
  const auto first = static_cast<std::uint32_t>(shape.gridVertices());
  for (int k = 0; k < count; ++k) {
    const std::size_t top = boundaryVertex(shape, k);
    mesh.positions.push_back(mesh.positions[3 * top]);
    mesh.positions.push_back(
        static_cast<float>(double{mesh.positions[3 * top + 1]} - input.skirtDepth));
    mesh.positions.push_back(mesh.positions[3 * top + 2]);
    for (std::size_t c = 0; c < 3; ++c)
      mesh.normals.push_back(mesh.normals[3 * top + c]);
    if (input.textureCoordinates)
      for (std::size_t c = 0; c < 2; ++c)
        mesh.uvs.push_back(mesh.uvs[2 * top + c]);
  }
  for (int k = 0; k < count; ++k) {
    const int next = (k + 1) % count;
    const std::uint32_t a = boundaryVertex(shape, k), b = boundaryVertex(shape, next);
    const std::uint32_t aLow = first + static_cast<std::uint32_t>(k);
    const std::uint32_t bLow = first + static_cast<std::uint32_t>(next);
    // The tile is on the left of the walk: (a, aLow, bLow) faces right, i.e. outward.
    mesh.indices.insert(mesh.indices.end(), {a, aLow, bLow, a, bLow, b});
  }
}

} // namespace

base::Result<Mesh> buildGridMesh(const MeshGridInput& input) {
  STRAHLER_RETURN_IF_ERROR(validate(input));
  const GridShape shape{input.quads};
  const bool skirt = input.skirtDepth > 0.0;
  const std::size_t n = static_cast<std::size_t>(input.quads);
  const std::size_t vertices = shape.gridVertices() + (skirt ? 4 * n : 0);
  const std::size_t corners = 6 * n * n + (skirt ? 24 * n : 0);
  Mesh mesh;
  mesh.origin = input.origin;
  mesh.positions.reserve(3 * vertices);
  mesh.normals.reserve(3 * vertices);
  if (input.textureCoordinates)
    mesh.uvs.reserve(2 * vertices);
  mesh.indices.reserve(corners);
  appendGridVertices(input, shape, mesh);
  appendGridTriangles(shape, mesh.indices);
  if (skirt)
    appendSkirt(input, shape, mesh);
  return mesh;
}

} // namespace strahler::encoding
