#pragma once
// An independent quantized-mesh-1.0 reader for tests, written from the format's specification
// (github.com/CesiumGS/quantized-mesh): it shares no code with the encoder, and throws
// std::runtime_error on any malformed or truncated tile.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace strahler::encoding::test_support {

/// One decoded tile, values as stored.
struct DecodedTile {
  std::array<double, 3> center{};
  float minimumHeight = 0.0f;
  float maximumHeight = 0.0f;
  std::array<double, 3> sphereCenter{};
  double sphereRadius = 0.0;
  std::array<double, 3> horizonOcclusionPoint{};
  std::vector<int> u, v, height;       ///< 0..32767, zig-zag deltas undone.
  int indexBytes = 0;                  ///< 2 or 4.
  std::size_t triangleCountOffset = 0; ///< Byte offset of triangleCount (after any padding).
  std::vector<std::uint32_t> indices;  ///< High-water marks undone.
  std::vector<std::uint32_t> west, south, east, north;
  std::vector<int> extensionOrder;                     ///< Extension ids as they came.
  std::map<int, std::vector<std::uint8_t>> extensions; ///< Id → payload.

  std::size_t vertexCount() const { return u.size(); }
  /// The decoded height of vertex k, m (as Cesium decodes it, in float32 bounds).
  double heightOf(std::size_t k) const {
    const double t = height[k] / 32767.0;
    return minimumHeight + t * (static_cast<double>(maximumHeight) - minimumHeight);
  }
};

/// Reads little-endian fields from a byte string.
class ByteReader {
public:
  explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}

  std::size_t position() const { return position_; }
  bool atEnd() const { return position_ == bytes_.size(); }
  void skip(std::size_t count) {
    need(count);
    position_ += count;
  }

  std::uint64_t unsignedOf(std::size_t width) {
    need(width);
    std::uint64_t value = 0;
    for (std::size_t k = 0; k < width; ++k)
      value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[position_ + k]))
               << (8 * k);
    position_ += width;
    return value;
  }
  std::uint8_t u8() { return static_cast<std::uint8_t>(unsignedOf(1)); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(unsignedOf(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(unsignedOf(4)); }
  double f64() {
    const std::uint64_t bits = unsignedOf(8);
    double value;
    static_assert(sizeof value == sizeof bits);
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  float f32() {
    const auto bits = static_cast<std::uint32_t>(unsignedOf(4));
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

private:
  void need(std::size_t count) const {
    if (bytes_.size() - position_ < count)
      throw std::runtime_error("tile truncated at byte " + std::to_string(position_));
  }

  const std::string& bytes_;
  std::size_t position_ = 0;
};

inline std::array<double, 3> readVector(ByteReader& in) {
  const double x = in.f64(), y = in.f64(), z = in.f64();
  return {x, y, z};
}

/// Undoes zig-zag delta coding of one 16-bit array.
inline std::vector<int> readZigZagDeltas(ByteReader& in, std::size_t count) {
  std::vector<int> values(count);
  int value = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const int code = in.u16();
    value += (code >> 1) ^ -(code & 1);
    if (value < 0 || value > 32767)
      throw std::runtime_error("quantized value out of 0..32767");
    values[k] = value;
  }
  return values;
}

inline std::vector<std::uint32_t> readEdge(ByteReader& in, int width, std::size_t vertices) {
  std::vector<std::uint32_t> list(in.u32());
  for (std::uint32_t& index : list) {
    index = static_cast<std::uint32_t>(in.unsignedOf(static_cast<std::size_t>(width)));
    if (index >= vertices)
      throw std::runtime_error("edge index out of range");
  }
  return list;
}

/// Decodes a whole tile; throws on malformed data or trailing bytes.
inline DecodedTile decodeQuantizedMesh(const std::string& bytes) {
  ByteReader in(bytes);
  DecodedTile tile;
  tile.center = readVector(in);
  tile.minimumHeight = in.f32();
  tile.maximumHeight = in.f32();
  tile.sphereCenter = readVector(in);
  tile.sphereRadius = in.f64();
  tile.horizonOcclusionPoint = readVector(in);
  if (in.position() != 88)
    throw std::runtime_error("header is not 88 bytes");

  const std::uint32_t vertexCount = in.u32();
  tile.u = readZigZagDeltas(in, vertexCount);
  tile.v = readZigZagDeltas(in, vertexCount);
  tile.height = readZigZagDeltas(in, vertexCount);

  // The spec: 32-bit indices above 64 Ki vertices, aligned to their size by padding.
  tile.indexBytes = vertexCount > 65536 ? 4 : 2;
  const auto width = static_cast<std::size_t>(tile.indexBytes);
  if (in.position() % width != 0)
    in.skip(width - in.position() % width);
  tile.triangleCountOffset = in.position();
  const std::uint32_t triangles = in.u32();
  tile.indices.resize(3 * static_cast<std::size_t>(triangles));
  std::uint32_t highest = 0;
  for (std::uint32_t& index : tile.indices) {
    const auto code = static_cast<std::uint32_t>(in.unsignedOf(width));
    if (code > highest)
      throw std::runtime_error("high-water-mark code above the mark");
    index = highest - code;
    if (code == 0)
      ++highest;
    if (index >= vertexCount)
      throw std::runtime_error("triangle index out of range");
  }
  tile.west = readEdge(in, tile.indexBytes, vertexCount);
  tile.south = readEdge(in, tile.indexBytes, vertexCount);
  tile.east = readEdge(in, tile.indexBytes, vertexCount);
  tile.north = readEdge(in, tile.indexBytes, vertexCount);

  while (!in.atEnd()) {
    const int id = in.u8();
    const std::uint32_t length = in.u32();
    std::vector<std::uint8_t> payload(length);
    for (std::uint8_t& byte : payload)
      byte = in.u8();
    tile.extensionOrder.push_back(id);
    tile.extensions[id] = std::move(payload);
  }
  return tile;
}

/// Cesium's oct decoding of two bytes (AttributeCompression.octDecode, range 255).
inline std::array<double, 3> octDecode(std::uint8_t xByte, std::uint8_t yByte) {
  double x = xByte / 255.0 * 2.0 - 1.0;
  double y = yByte / 255.0 * 2.0 - 1.0;
  const double z = 1.0 - (std::fabs(x) + std::fabs(y));
  if (z < 0.0) {
    const double oldX = x;
    x = (1.0 - std::fabs(y)) * (oldX < 0.0 ? -1.0 : 1.0);
    y = (1.0 - std::fabs(oldX)) * (y < 0.0 ? -1.0 : 1.0);
  }
  const double length = std::sqrt(x * x + y * y + z * z);
  return {x / length, y / length, z / length};
}

} // namespace strahler::encoding::test_support
