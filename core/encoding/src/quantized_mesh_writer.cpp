#include "quantized_mesh_writer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <utility>

namespace strahler::encoding::qm {
namespace {

using wgs84::Ecef;

constexpr int kQuantizedMax = 32767;
constexpr std::size_t kIndices32Above = 64 * 1024;
constexpr double kDegrees = std::numbers::pi / 180.0;
/// Where the horizon point goes, in scaled radii, when Cesium's construction has none (a tile
/// as wide as a hemisphere): far along the tile's direction, culled only from behind the globe.
constexpr double kFarHorizonPoint = 1.0e6;

enum ExtensionId : std::uint8_t { kOctNormals = 1, kWaterMask = 2, kMetadata = 4 };

/// Appends little-endian values.
class ByteWriter {
public:
  explicit ByteWriter(std::size_t reserve) { bytes_.reserve(reserve); }

  template <class T> void put(T value) {
    static_assert(std::endian::native == std::endian::little, "writes host order");
    const std::size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &value, sizeof(T));
  }

  /// Values of one type in a row, as `put` would write them one by one.
  template <class T> void putAll(std::span<const T> values) {
    const std::size_t at = bytes_.size();
    bytes_.resize(at + values.size_bytes());
    std::memcpy(bytes_.data() + at, values.data(), values.size_bytes());
  }

  void putBytes(std::span<const std::uint8_t> data) {
    bytes_.append(reinterpret_cast<const char*>(data.data()), data.size());
  }

  void putBytes(const std::string& data) { bytes_.append(data); }

  void padTo(std::size_t alignment) {
    while (bytes_.size() % alignment != 0)
      bytes_.push_back('\0');
  }

  std::string take() && { return std::move(bytes_); }

private:
  std::string bytes_;
};

/// The float32 bounds Cesium decodes heights with, rounded outward from the true ones.
std::pair<float, float> heightBounds(const std::vector<Vertex>& vertices) {
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const Vertex& v : vertices) {
    low = std::min(low, v.height);
    high = std::max(high, v.height);
  }
  auto lowF = static_cast<float>(low);
  auto highF = static_cast<float>(high);
  if (static_cast<double>(lowF) > low)
    lowF = std::nextafter(lowF, -std::numeric_limits<float>::infinity());
  if (static_cast<double>(highF) < high)
    highF = std::nextafter(highF, std::numeric_limits<float>::infinity());
  return {lowF, highF};
}

Ecef scaledDirection(const Ecef& direction) {
  Ecef s{direction[0] / wgs84::kSemiMajorAxis, direction[1] / wgs84::kSemiMajorAxis,
         direction[2] / wgs84::kSemiMinorAxis};
  const double length = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  for (double& c : s)
    c /= length;
  return s;
}

void writeHeader(ByteWriter& out, const TileData& tile, float minHeight, float maxHeight) {
  const GeographicRect& r = tile.rect;
  const Ecef centre =
      wgs84::toEcef(0.5 * (r.west + r.east) * kDegrees, 0.5 * (r.south + r.north) * kDegrees,
                    0.5 * (static_cast<double>(minHeight) + maxHeight));
  std::vector<Ecef> positions;
  positions.reserve(tile.vertices.size());
  for (const Vertex& v : tile.vertices)
    positions.push_back(v.position);
  const wgs84::Sphere sphere = wgs84::enclosingSphere(positions);
  std::optional<Ecef> horizon = wgs84::horizonOcclusionPoint(sphere.centre, positions, minHeight);
  if (!horizon) {
    const Ecef towards = scaledDirection(centre);
    horizon = Ecef{towards[0] * kFarHorizonPoint, towards[1] * kFarHorizonPoint,
                   towards[2] * kFarHorizonPoint};
  }
  for (double c : centre)
    out.put(c);
  out.put(minHeight);
  out.put(maxHeight);
  for (double c : sphere.centre)
    out.put(c);
  out.put(sphere.radius);
  for (double c : *horizon)
    out.put(c);
}

std::uint16_t zigZag(int delta) {
  return static_cast<std::uint16_t>(delta >= 0 ? 2 * delta : -2 * delta - 1);
}

/// Grid position k of `cells` on the 0..32767 scale, rounded half up.
int quantizeGrid(int k, int cells) {
  return (2 * k * kQuantizedMax + cells) / (2 * cells);
}

/// One of the u, v and height arrays: zig-zag coded differences of consecutive values.
template <class Quantize>
void writeDeltas(ByteWriter& out, const std::vector<Vertex>& vertices, Quantize quantize) {
  std::vector<std::uint16_t> codes(vertices.size());
  int previous = 0;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const int value = quantize(vertices[k]);
    codes[k] = zigZag(value - previous);
    previous = value;
  }
  out.putAll(std::span<const std::uint16_t>(codes));
}

void writeVertices(ByteWriter& out, const TileData& tile, float minHeight, float maxHeight) {
  const int cells = tile.samples - 1;
  out.put(static_cast<std::uint32_t>(tile.vertices.size()));
  writeDeltas(out, tile.vertices,
              [cells](const Vertex& v) { return quantizeGrid(v.column, cells); });
  writeDeltas(out, tile.vertices, [cells](const Vertex& v) { return quantizeGrid(v.row, cells); });
  const double range = static_cast<double>(maxHeight) - minHeight;
  writeDeltas(out, tile.vertices, [&](const Vertex& v) {
    const double t = range > 0.0 ? (v.height - minHeight) / range : 0.0;
    return std::clamp(static_cast<int>(std::floor(t * kQuantizedMax + 0.5)), 0, kQuantizedMax);
  });
}

template <class Index> void writeIndices(ByteWriter& out, const TileData& tile) {
  out.padTo(sizeof(Index));
  out.put(static_cast<std::uint32_t>(tile.triangles.size() / 3));
  // High-water mark: each index as the distance below the highest index so far plus one.
  std::vector<Index> codes(tile.triangles.size());
  std::uint32_t highest = 0;
  for (std::size_t k = 0; k < codes.size(); ++k) {
    const std::uint32_t index = tile.triangles[k];
    codes[k] = static_cast<Index>(highest - index);
    if (index == highest)
      ++highest;
  }
  out.putAll(std::span<const Index>(codes));
  const int last = tile.samples - 1;
  const auto edge = [&](auto onEdge, auto along) {
    std::vector<std::uint32_t> list;
    for (std::size_t k = 0; k < tile.vertices.size(); ++k)
      if (onEdge(tile.vertices[k]))
        list.push_back(static_cast<std::uint32_t>(k));
    std::sort(list.begin(), list.end(), [&](std::uint32_t p, std::uint32_t q) {
      return along(tile.vertices[p]) < along(tile.vertices[q]);
    });
    out.put(static_cast<std::uint32_t>(list.size()));
    const std::vector<Index> narrow(list.begin(), list.end());
    out.putAll(std::span<const Index>(narrow));
  };
  const auto row = [](const Vertex& v) { return v.row; };
  const auto column = [](const Vertex& v) { return v.column; };
  edge([](const Vertex& v) { return v.column == 0; }, row);
  edge([](const Vertex& v) { return v.row == 0; }, column);
  edge([last](const Vertex& v) { return v.column == last; }, row);
  edge([last](const Vertex& v) { return v.row == last; }, column);
}

void writeExtensions(ByteWriter& out, const TileData& tile, const QuantizedMeshOptions& options) {
  if (!tile.normals.empty()) {
    out.put(static_cast<std::uint8_t>(kOctNormals));
    out.put(static_cast<std::uint32_t>(tile.normals.size()));
    out.putBytes(tile.normals);
  }
  if (!options.waterMask.empty()) {
    out.put(static_cast<std::uint8_t>(kWaterMask));
    out.put(static_cast<std::uint32_t>(options.waterMask.size()));
    out.putBytes(options.waterMask);
  }
  if (!options.metadata.empty()) {
    out.put(static_cast<std::uint8_t>(kMetadata));
    out.put(static_cast<std::uint32_t>(4 + options.metadata.size()));
    out.put(static_cast<std::uint32_t>(options.metadata.size()));
    out.putBytes(options.metadata);
  }
}

} // namespace

std::string writeTile(const TileData& tile, const QuantizedMeshOptions& options) {
  const std::size_t vertices = tile.vertices.size();
  const bool wide = vertices > kIndices32Above;
  const std::size_t indexBytes = wide ? 4 : 2;
  ByteWriter out(88 + 4 + 6 * vertices + 4 + indexBytes * (tile.triangles.size() + 4 * 64) + 32 +
                 tile.normals.size() + 5 + options.waterMask.size() + 9 + options.metadata.size());
  const auto [minHeight, maxHeight] = heightBounds(tile.vertices);
  writeHeader(out, tile, minHeight, maxHeight);
  writeVertices(out, tile, minHeight, maxHeight);
  if (wide)
    writeIndices<std::uint32_t>(out, tile);
  else
    writeIndices<std::uint16_t>(out, tile);
  writeExtensions(out, tile, options);
  return std::move(out).take();
}

} // namespace strahler::encoding::qm
