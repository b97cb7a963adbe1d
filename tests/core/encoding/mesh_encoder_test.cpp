#include "result_matchers.h"
#include "synthetic_terrain.h"

#include "strahler/encoding/mesh.h"
#include "strahler/encoding/mesh_encoder.h"

#include <draco/attributes/attribute_quantization_transform.h>
#include <draco/compression/decode.h>
#include <draco/core/decoder_buffer.h>
#include <draco/mesh/mesh.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace strahler::encoding {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// The attributes and triangles of a decoded Draco mesh, one entry per decoded point.
struct Decoded {
  std::vector<std::array<float, 3>> positions, normals;
  std::vector<std::array<float, 2>> uvs;
  std::vector<std::array<std::uint32_t, 3>> faces;
};

template <int N>
std::vector<std::array<float, N>> readAttribute(const draco::Mesh& mesh,
                                                draco::GeometryAttribute::Type type) {
  std::vector<std::array<float, N>> values;
  const draco::PointAttribute* attribute = mesh.GetNamedAttribute(type);
  if (attribute == nullptr)
    return values;
  for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
    std::array<float, N> value{};
    attribute->ConvertValue<float, N>(attribute->mapped_index(p), value.data());
    values.push_back(value);
  }
  return values;
}

Decoded extract(const draco::Mesh& mesh) {
  Decoded out;
  out.positions = readAttribute<3>(mesh, draco::GeometryAttribute::POSITION);
  out.normals = readAttribute<3>(mesh, draco::GeometryAttribute::NORMAL);
  out.uvs = readAttribute<2>(mesh, draco::GeometryAttribute::TEX_COORD);
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    const auto& face = mesh.face(f);
    out.faces.push_back({face[0].value(), face[1].value(), face[2].value()});
  }
  return out;
}

Decoded decodeDrc(const std::string& bytes) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  draco::Decoder decoder;
  auto mesh = decoder.DecodeMeshFromBuffer(&buffer);
  EXPECT_TRUE(mesh.ok()) << mesh.status().error_msg_string();
  return mesh.ok() ? extract(*mesh.value()) : Decoded{};
}

Mesh tile(int quads, bool uv, geometry::Vec2 origin = {2000.0, -1000.0}) {
  auto mesh = buildGridMesh(test_support::syntheticTile(quads, 30.0, origin, 60.0, uv));
  return strahler::test_support::valueOf(std::move(mesh));
}

std::string drc(const Mesh& mesh, const DracoOptions& options = {}) {
  auto bytes = encodeDraco(mesh, options);
  EXPECT_TRUE(bytes.ok()) << (bytes.ok() ? "" : bytes.error().message);
  return bytes.ok() ? std::move(bytes).value() : std::string{};
}

std::string glb(const Mesh& mesh, const DracoOptions& options = {}) {
  auto bytes = encodeGlb(mesh, options);
  EXPECT_TRUE(bytes.ok()) << (bytes.ok() ? "" : bytes.error().message);
  return bytes.ok() ? std::move(bytes).value() : std::string{};
}

/// For each decoded point, the original vertex it came from: the one in the same (x, z)
/// cell whose position is closest. Draco reorders points and triangles, not their values.
std::vector<std::uint32_t> matchPoints(const Mesh& mesh, const Decoded& decoded, double cellX,
                                       double cellZ) {
  std::map<std::pair<long long, long long>, std::vector<std::uint32_t>> cells;
  const auto key = [&](double x, double z) {
    return std::make_pair(std::llround(x / cellX), std::llround(z / cellZ));
  };
  for (std::uint32_t v = 0; v < mesh.positions.size() / 3; ++v)
    cells[key(mesh.positions[3 * v], mesh.positions[3 * v + 2])].push_back(v);
  std::vector<std::uint32_t> original;
  for (const auto& p : decoded.positions) {
    std::uint32_t best = UINT32_MAX;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::uint32_t v : cells[key(p[0], p[2])]) {
      double distance = 0.0;
      for (std::size_t c = 0; c < 3; ++c)
        distance = std::max(distance, std::fabs(double{p[c]} - mesh.positions[3 * v + c]));
      if (distance < bestDistance)
        std::tie(best, bestDistance) = std::make_pair(v, distance);
    }
    original.push_back(best);
  }
  return original;
}

std::array<std::uint32_t, 3> rotateSmallestFirst(std::array<std::uint32_t, 3> face) {
  while (face[0] > face[1] || face[0] > face[2])
    face = {face[1], face[2], face[0]};
  return face;
}

/// How the decoded v relates to the Mesh's: Draco's own v-up convention (.drc) or glTF's.
enum class V { kFlipped, kAsInMesh };

/// Checks the decoded mesh against the original: same counts, every point within
/// `maxError` per coordinate of a distinct original vertex, normals within half a degree,
/// uvs within 2.5e-4, the same triangles with the same winding.
void expectRoundTrip(const Mesh& mesh, const Decoded& decoded, double maxError, double cellX,
                     double cellZ, V convention = V::kFlipped) {
  const std::size_t vertices = mesh.positions.size() / 3;
  ASSERT_EQ(decoded.positions.size(), vertices);
  ASSERT_EQ(decoded.normals.size(), vertices);
  ASSERT_EQ(decoded.uvs.size(), mesh.uvs.size() / 2);
  ASSERT_EQ(decoded.faces.size() * 3, mesh.indices.size());
  const std::vector<std::uint32_t> original = matchPoints(mesh, decoded, cellX, cellZ);
  ASSERT_EQ(std::set<std::uint32_t>(original.begin(), original.end()).size(), vertices);
  for (std::size_t p = 0; p < vertices; ++p) {
    const std::size_t v = original[p];
    for (std::size_t c = 0; c < 3; ++c)
      ASSERT_LE(std::fabs(double{decoded.positions[p][c]} - mesh.positions[3 * v + c]), maxError)
          << "point " << p << " coordinate " << c;
    double cosine = 0.0;
    for (std::size_t c = 0; c < 3; ++c)
      cosine += double{decoded.normals[p][c]} * mesh.normals[3 * v + c];
    ASSERT_GT(cosine, std::cos(0.5 * kPi / 180.0)) << "normal of point " << p;
    if (!decoded.uvs.empty()) {
      ASSERT_NEAR(decoded.uvs[p][0], mesh.uvs[2 * v], 2.5e-4);
      const float expectedV =
          convention == V::kFlipped ? 1.0f - mesh.uvs[2 * v + 1] : mesh.uvs[2 * v + 1];
      ASSERT_NEAR(decoded.uvs[p][1], expectedV, 2.5e-4);
    }
  }
  std::set<std::array<std::uint32_t, 3>> faces;
  for (std::size_t f = 0; f < mesh.indices.size(); f += 3)
    faces.insert(rotateSmallestFirst({mesh.indices[f], mesh.indices[f + 1], mesh.indices[f + 2]}));
  for (const auto& face : decoded.faces)
    ASSERT_EQ(
        faces.count(rotateSmallestFirst({original[face[0]], original[face[1]], original[face[2]]})),
        1u);
}

TEST(DracoEncoding, RoundTripsThroughDracosDecoder) {
  const Mesh mesh = tile(64, true);
  const DracoOptions options;
  expectRoundTrip(mesh, decodeDrc(drc(mesh, options)), options.maxPositionError, 30.0, 30.0);
}

TEST(DracoEncoding, RoundTripsWithoutTextureCoordinatesAtEverySpeed) {
  const Mesh mesh = tile(16, false);
  for (int speed = 0; speed <= 10; ++speed) {
    SCOPED_TRACE(speed);
    DracoOptions options;
    options.speed = speed;
    options.maxPositionError = 0.002;
    expectRoundTrip(mesh, decodeDrc(drc(mesh, options)), options.maxPositionError, 30.0, 30.0);
  }
}

TEST(DracoEncoding, SameMeshGivesSameBytes) {
  const std::string first = drc(tile(32, true));
  EXPECT_FALSE(first.empty());
  EXPECT_EQ(first, drc(tile(32, true)));
  EXPECT_NE(first, drc(tile(32, false)));
  const std::string firstGlb = glb(tile(32, true));
  EXPECT_EQ(firstGlb, glb(tile(32, true)));
}

TEST(PositionBits, FollowsTheHalfStepRule) {
  // 5000 / (2·0.01) + 1 = 250001 → 18 bits (2^17 − 1 = 131071 steps would be too coarse).
  EXPECT_EQ(positionBitsFor(5000.0, 0.01), 18);
  EXPECT_LE(5000.0 / ((1 << 18) - 1) / 2, 0.01);
  EXPECT_GT(5000.0 / ((1 << 17) - 1) / 2, 0.01);
  EXPECT_EQ(positionBitsFor(1920.0, 0.01), 17);              // 96001 → 2^17 − 1 = 131071
  EXPECT_EQ(positionBitsFor(2.0 * 0.01 * 1023.0, 0.01), 10); // exactly on the boundary
  EXPECT_EQ(positionBitsFor(1.0, 0.01), 8);                  // clamped up
  EXPECT_EQ(positionBitsFor(0.0, 0.01), 8);
  EXPECT_EQ(positionBitsFor(1e9, 1e-9), 30); // clamped down
  EXPECT_EQ(positionBitsFor(100.0, 0.0), 30);
  EXPECT_EQ(positionBitsFor(std::numeric_limits<double>::infinity(), 0.01), 30);
}

/// A 5 km × 2 km × 3 km (east × up × south) mesh: 33 × 33 points over rough heights.
Mesh largeExtentMesh() {
  Mesh mesh;
  const int side = 33;
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      const double h = (i + j == 0) ? 0.0 : (i + j == 2 * side - 2) ? 2000.0 : 1000.0;
      const double bumps = std::sin(i * 1.7) * std::cos(j * 2.3) * 900.0;
      mesh.positions.push_back(static_cast<float>(i * 5000.0 / (side - 1)));
      mesh.positions.push_back(static_cast<float>(h + (i + j == 0 || h > 1500.0 ? 0.0 : bumps)));
      mesh.positions.push_back(static_cast<float>(-j * 3000.0 / (side - 1)));
      mesh.normals.insert(mesh.normals.end(), {0.0f, 1.0f, 0.0f});
    }
  }
  for (std::uint32_t j = 0; j + 1 < side; ++j) {
    for (std::uint32_t i = 0; i + 1 < side; ++i) {
      const std::uint32_t sw = j * side + i, se = sw + 1, nw = sw + side, ne = nw + 1;
      mesh.indices.insert(mesh.indices.end(), {sw, se, ne, sw, ne, nw});
    }
  }
  return mesh;
}

TEST(DracoEncoding, KeepsACentimetreOverAFiveKilometreExtent) {
  const Mesh mesh = largeExtentMesh();
  const Decoded decoded = decodeDrc(drc(mesh));
  expectRoundTrip(mesh, decoded, 0.01, 5000.0 / 32, 3000.0 / 32);
  double worst = 0.0;
  const std::vector<std::uint32_t> original = matchPoints(mesh, decoded, 5000.0 / 32, 3000.0 / 32);
  for (std::size_t p = 0; p < decoded.positions.size(); ++p)
    worst = std::max(worst,
                     std::fabs(double{decoded.positions[p][0]} - mesh.positions[3 * original[p]]));
  EXPECT_GT(worst, 0.001) << "positions are quantised, not stored losslessly";
}

/// The position quantisation bits stored in a .drc, read back by Draco's decoder.
int storedPositionBits(const std::string& bytes) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  draco::Decoder decoder;
  decoder.SetSkipAttributeTransform(draco::GeometryAttribute::POSITION);
  auto mesh = decoder.DecodeMeshFromBuffer(&buffer);
  EXPECT_TRUE(mesh.ok());
  draco::AttributeQuantizationTransform transform;
  if (!mesh.ok() || !transform.InitFromAttribute(
                        *mesh.value()->GetNamedAttribute(draco::GeometryAttribute::POSITION)))
    return -1;
  return transform.quantization_bits();
}

TEST(DracoEncoding, StoresTheDocumentedPositionBits) {
  EXPECT_EQ(storedPositionBits(drc(tile(64, true))), 17);    // 1.92 km tile, 1 cm
  EXPECT_EQ(storedPositionBits(drc(largeExtentMesh())), 19); // 5 km: 18 + float rounding
  DracoOptions coarse;
  coarse.maxPositionError = 0.5;
  EXPECT_EQ(storedPositionBits(drc(tile(64, true), coarse)), 11); // 1920 / 1 + 1 → 2^11 − 1
}

TEST(DracoEncoding, RejectsInvalidMeshesAndOptions) {
  const Mesh good = tile(4, true);
  std::vector<Mesh> badMeshes(5, good);
  badMeshes[0] = Mesh{};
  badMeshes[1].indices[7] = static_cast<std::uint32_t>(good.positions.size() / 3);
  badMeshes[2].normals.pop_back();
  badMeshes[3].uvs.resize(4);
  badMeshes[4].positions[5] = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t k = 0; k < badMeshes.size(); ++k) {
    for (const auto& result : {encodeDraco(badMeshes[k]), encodeGlb(badMeshes[k])}) {
      ASSERT_FALSE(result.ok()) << "mesh case " << k;
      EXPECT_EQ(result.error().code, base::ErrorCode::kInvalidInput) << "mesh case " << k;
    }
  }
  std::vector<DracoOptions> badOptions(6);
  badOptions[0].speed = 11;
  badOptions[1].speed = -1;
  badOptions[2].maxPositionError = 0.0;
  badOptions[3].maxPositionError = std::numeric_limits<double>::quiet_NaN();
  badOptions[4].normalBits = 0;
  badOptions[5].uvBits = 31;
  for (std::size_t k = 0; k < badOptions.size(); ++k) {
    for (const auto& result : {encodeDraco(good, badOptions[k]), encodeGlb(good, badOptions[k])}) {
      ASSERT_FALSE(result.ok()) << "options case " << k;
      EXPECT_EQ(result.error().code, base::ErrorCode::kInvalidInput) << "options case " << k;
    }
  }
}

TEST(DracoEncoding, RefusesAnErrorFloatCoordinatesCannotKeep) {
  // 1.92 km of float32 coordinates: 0.8 mm takes 24 bits, 0.7 mm would take 27.
  DracoOptions options;
  options.maxPositionError = 0.0007;
  for (const auto& result :
       {encodeDraco(tile(64, false), options), encodeGlb(tile(64, false), options)}) {
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().code, base::ErrorCode::kInvalidInput);
    EXPECT_NE(result.error().message.find("float32"), std::string::npos) << result.error().message;
  }
  options.maxPositionError = 0.0008;
  const Mesh mesh = tile(64, false);
  const std::string bytes = drc(mesh, options);
  EXPECT_EQ(storedPositionBits(bytes), 24);
  expectRoundTrip(mesh, decodeDrc(bytes), options.maxPositionError, 30.0, 30.0);
}

std::uint32_t readU32(const std::string& bytes, std::size_t offset) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  return value; // glb is little-endian, as is every machine we build on
}

/// The JSON chunk of a .glb, after checking the 12-byte header and the chunk framing.
nlohmann::json glbJson(const std::string& bytes) {
  EXPECT_GE(bytes.size(), 20u);
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_EQ(readU32(bytes, 4), 2u);
  EXPECT_EQ(readU32(bytes, 8), bytes.size());
  const std::uint32_t jsonLength = readU32(bytes, 12);
  EXPECT_EQ(readU32(bytes, 16), 0x4E4F534Au); // "JSON"
  return nlohmann::json::parse(bytes.substr(20, jsonLength));
}

TEST(GlbEncoding, DeclaresDracoCompressionAndTranslatesTheNodeToTheTile) {
  const Mesh mesh = tile(16, true, {123456.75, -65432.5});
  const nlohmann::json gltf = glbJson(glb(mesh));
  EXPECT_EQ(gltf["asset"]["version"], "2.0");
  EXPECT_NE(std::find(gltf["extensionsRequired"].begin(), gltf["extensionsRequired"].end(),
                      "KHR_draco_mesh_compression"),
            gltf["extensionsRequired"].end());
  ASSERT_EQ(gltf["nodes"].size(), 1u);
  const nlohmann::json& translation = gltf["nodes"][0]["translation"];
  ASSERT_EQ(translation.size(), 3u);
  EXPECT_EQ(translation[0].get<double>(), 123456.75);
  EXPECT_EQ(translation[1].get<double>(), 0.0);
  EXPECT_EQ(translation[2].get<double>(), 65432.5);
  const nlohmann::json& primitive = gltf["meshes"][0]["primitives"][0];
  EXPECT_TRUE(primitive["extensions"].contains("KHR_draco_mesh_compression"));
  EXPECT_TRUE(primitive["attributes"].contains("TEXCOORD_0"));
}

/// The Draco bitstream a .glb's only primitive points to, from its binary chunk.
std::string embeddedDraco(const std::string& bytes, const nlohmann::json& gltf) {
  const std::size_t jsonEnd = 20 + readU32(bytes, 12);
  EXPECT_EQ(readU32(bytes, jsonEnd + 4), 0x004E4942u); // "BIN\0"
  const std::string bin = bytes.substr(jsonEnd + 8, readU32(bytes, jsonEnd));
  const nlohmann::json& draco =
      gltf["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"];
  const nlohmann::json& view = gltf["bufferViews"][draco["bufferView"].get<std::size_t>()];
  return bin.substr(view.value("byteOffset", std::size_t{0}),
                    view["byteLength"].get<std::size_t>());
}

TEST(GlbEncoding, EmbedsADracoMeshThatRoundTrips) {
  const Mesh mesh = tile(32, true, {-4096.0, 8192.0});
  const std::string bytes = glb(mesh);
  const nlohmann::json gltf = glbJson(bytes);
  const nlohmann::json& primitive = gltf["meshes"][0]["primitives"][0];
  EXPECT_EQ(gltf["accessors"][primitive["attributes"]["POSITION"].get<std::size_t>()]["count"],
            mesh.positions.size() / 3);
  EXPECT_EQ(gltf["accessors"][primitive["indices"].get<std::size_t>()]["count"],
            mesh.indices.size());
  // In glTF, v runs downwards as in the Mesh: Draco's glTF writer flips it back.
  expectRoundTrip(mesh, decodeDrc(embeddedDraco(bytes, gltf)), 0.01, 30.0, 30.0, V::kAsInMesh);
}

} // namespace
} // namespace strahler::encoding
