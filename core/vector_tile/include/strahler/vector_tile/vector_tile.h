#pragma once

#include "strahler/base/result.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace strahler::vector_tile {

/// The extent most clients expect: tile coordinates run from 0 to 4096 on both axes.
inline constexpr std::uint32_t kDefaultExtent = 4096;

/// A point in tile coordinates: x east, y down (south), 0..extent inside the tile.
struct Point {
  std::int32_t x = 0;
  std::int32_t y = 0;

  friend bool operator==(const Point&, const Point&) = default;
};

/// The geometry type of a feature (MVT 2.1, 4.3.4).
enum class GeometryType { kUnknown = 0, kPoint = 1, kLineString = 2, kPolygon = 3 };

/// An attribute value: a string, a double, a signed integer or a boolean.
using Value = std::variant<std::string, double, std::int64_t, bool>;

/// One attribute of a feature: its key and value.
using Property = std::pair<std::string, Value>;

/// A feature: kPoint parts are single points (several: a multipoint), kLineString parts are
/// lines of ≥ 2 points, kPolygon parts are rings without the closing point, exterior rings
/// clockwise in tile coordinates (positive area, y down) each followed by its interior rings
/// (counter-clockwise).
struct Feature {
  GeometryType type = GeometryType::kUnknown;
  std::vector<std::vector<Point>> parts; ///< The geometry, in tile coordinates.
  std::vector<Property> properties;      ///< Attributes, in order; keys unique.
  std::uint64_t id = 0;                  ///< 0: none.

  friend bool operator==(const Feature&, const Feature&) = default;
};

/// A named layer of features sharing one extent.
struct Layer {
  std::string name;                      ///< Unique within the tile.
  std::uint32_t extent = kDefaultExtent; ///< Tile coordinates per side.
  std::vector<Feature> features;         ///< In order.

  friend bool operator==(const Layer&, const Layer&) = default;
};

/// A vector tile: its layers, in order.
struct Tile {
  std::vector<Layer> layers; ///< Layers without features are left out of the bytes.

  friend bool operator==(const Tile&, const Tile&) = default;
};

/// Twice the signed area of a ring by the spec's surveyor's formula (4.3.4.4): positive for
/// an exterior ring (clockwise with y down), negative for an interior one.
std::int64_t ringArea2(const std::vector<Point>& ring) noexcept;

/// The MVT 2.1 bytes of `tile` (version 2 layers; keys and values deduplicated per layer).
/// Consecutive repeated points are dropped; a line left with < 2 points or a ring with < 3 is
/// dropped, and a feature left without parts, and a layer without features.
std::string encodeTile(const Tile& tile);

/// The tile in `bytes`; kInvalidInput for bytes that are not a valid MVT (bad protobuf, a tag
/// or command outside its table, a geometry that breaks the command grammar).
base::Result<Tile> decodeTile(std::string_view bytes);

} // namespace strahler::vector_tile
