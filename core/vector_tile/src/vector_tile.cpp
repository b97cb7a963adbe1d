#include "strahler/vector_tile/vector_tile.h"

#include "mvt/vector_tile.pb.h"

#include <map>

namespace strahler::vector_tile {
namespace {

namespace pb = strahler::mvt;

constexpr std::uint32_t kMoveTo = 1, kLineTo = 2, kClosePath = 7;

std::uint32_t command(std::uint32_t id, std::size_t count) {
  return (id & 7u) | (static_cast<std::uint32_t>(count) << 3);
}
std::uint32_t zigzag(std::int32_t v) {
  return (static_cast<std::uint32_t>(v) << 1) ^ static_cast<std::uint32_t>(v >> 31);
}
std::int32_t unzigzag(std::uint32_t v) {
  return static_cast<std::int32_t>(v >> 1) ^ -static_cast<std::int32_t>(v & 1u);
}

/// `part` without consecutive repeats (and, for rings, without a closing repeat of the first).
std::vector<Point> withoutRepeats(const std::vector<Point>& part, bool ring) {
  std::vector<Point> out;
  out.reserve(part.size());
  for (const Point& p : part)
    if (out.empty() || !(out.back() == p))
      out.push_back(p);
  while (ring && out.size() > 1 && out.back() == out.front())
    out.pop_back();
  return out;
}

/// Appends the commands of `feature`'s geometry to `out`; false when no part is left.
bool encodeGeometry(const Feature& feature, pb::Tile::Feature& out) {
  Point cursor;
  const auto move = [&](const Point& p) {
    out.add_geometry(zigzag(p.x - cursor.x));
    out.add_geometry(zigzag(p.y - cursor.y));
    cursor = p;
  };
  if (feature.type == GeometryType::kPoint) {
    std::vector<Point> points;
    for (const auto& part : feature.parts)
      points.insert(points.end(), part.begin(), part.end());
    if (points.empty())
      return false;
    out.add_geometry(command(kMoveTo, points.size()));
    for (const Point& p : points)
      move(p);
    return true;
  }
  const bool ring = feature.type == GeometryType::kPolygon;
  bool any = false;
  for (const auto& raw : feature.parts) {
    const std::vector<Point> part = withoutRepeats(raw, ring);
    if (part.size() < (ring ? 3u : 2u))
      continue;
    out.add_geometry(command(kMoveTo, 1));
    move(part.front());
    out.add_geometry(command(kLineTo, part.size() - 1));
    for (std::size_t i = 1; i < part.size(); ++i)
      move(part[i]);
    if (ring)
      out.add_geometry(command(kClosePath, 1));
    any = true;
  }
  return any;
}

pb::Tile::Value toProto(const Value& value) {
  pb::Tile::Value v;
  if (const auto* s = std::get_if<std::string>(&value))
    v.set_string_value(*s);
  else if (const auto* d = std::get_if<double>(&value))
    v.set_double_value(*d);
  else if (const auto* i = std::get_if<std::int64_t>(&value))
    v.set_sint_value(*i);
  else
    v.set_bool_value(std::get<bool>(value));
  return v;
}

/// Keys and values of one layer, each stored once; a value's identity is its type and bits.
class TagTable {
public:
  explicit TagTable(pb::Tile::Layer& layer) : layer_(layer) {}

  void tag(const Property& property, pb::Tile::Feature& feature) {
    const auto [k, newKey] = keys_.try_emplace(property.first, keys_.size());
    if (newKey)
      layer_.add_keys(property.first);
    std::string valueKey = toProto(property.second).SerializeAsString();
    const auto [v, newValue] = values_.try_emplace(std::move(valueKey), values_.size());
    if (newValue)
      *layer_.add_values() = toProto(property.second);
    feature.add_tags(static_cast<std::uint32_t>(k->second));
    feature.add_tags(static_cast<std::uint32_t>(v->second));
  }

private:
  pb::Tile::Layer& layer_;
  std::map<std::string, std::size_t> keys_;
  std::map<std::string, std::size_t> values_;
};

base::Error bad(const std::string& why) {
  return base::makeError(base::ErrorCode::kInvalidInput, "not a vector tile: " + why);
}

base::Result<Value> fromProto(const pb::Tile::Value& v) {
  if (v.has_string_value())
    return Value{v.string_value()};
  if (v.has_double_value())
    return Value{v.double_value()};
  if (v.has_float_value())
    return Value{static_cast<double>(v.float_value())};
  if (v.has_sint_value())
    return Value{static_cast<std::int64_t>(v.sint_value())};
  if (v.has_int_value())
    return Value{static_cast<std::int64_t>(v.int_value())};
  if (v.has_uint_value())
    return Value{static_cast<std::int64_t>(v.uint_value())};
  if (v.has_bool_value())
    return Value{v.bool_value()};
  return bad("a value without a type");
}

/// The parts of a geometry command stream (spec 4.3), checked against the command grammar.
base::Result<std::vector<std::vector<Point>>> decodeGeometry(const pb::Tile::Feature& f) {
  std::vector<std::vector<Point>> parts;
  Point cursor;
  const int n = f.geometry_size();
  for (int i = 0; i < n;) {
    const std::uint32_t id = f.geometry(i) & 7u, count = f.geometry(i) >> 3;
    ++i;
    if (id == kClosePath) {
      if (count != 1 || parts.empty() || f.type() != pb::Tile::POLYGON)
        return bad("a misplaced ClosePath");
      continue;
    }
    if (id != kMoveTo && id != kLineTo)
      return bad("unknown command " + std::to_string(id));
    if (count == 0 || n - i < 2 * static_cast<std::int64_t>(count))
      return bad("a command without its parameters");
    if (id == kLineTo && parts.empty())
      return bad("a LineTo before any MoveTo");
    for (std::uint32_t k = 0; k < count; ++k, i += 2) {
      cursor = {cursor.x + unzigzag(f.geometry(i)), cursor.y + unzigzag(f.geometry(i + 1))};
      if (id == kMoveTo)
        parts.emplace_back();
      parts.back().push_back(cursor);
    }
  }
  return parts;
}

base::Result<Layer> decodeLayer(const pb::Tile::Layer& l) {
  Layer layer;
  layer.name = l.name();
  layer.extent = l.extent();
  std::vector<Value> values;
  for (const pb::Tile::Value& v : l.values()) {
    STRAHLER_ASSIGN_OR_RETURN(Value value, fromProto(v));
    values.push_back(std::move(value));
  }
  for (const pb::Tile::Feature& f : l.features()) {
    Feature feature;
    feature.id = f.id();
    feature.type = static_cast<GeometryType>(f.type());
    if (f.tags_size() % 2 != 0)
      return bad("an odd number of tags");
    for (int t = 0; t < f.tags_size(); t += 2) {
      const std::uint32_t k = f.tags(t), v = f.tags(t + 1);
      if (k >= static_cast<std::uint32_t>(l.keys_size()) || v >= values.size())
        return bad("a tag outside the keys or values of layer '" + layer.name + "'");
      feature.properties.emplace_back(l.keys(static_cast<int>(k)), values[v]);
    }
    STRAHLER_ASSIGN_OR_RETURN(feature.parts, decodeGeometry(f));
    layer.features.push_back(std::move(feature));
  }
  return layer;
}

} // namespace

std::int64_t ringArea2(const std::vector<Point>& ring) noexcept {
  std::int64_t sum = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point& a = ring[i];
    const Point& b = ring[(i + 1) % n];
    sum += std::int64_t{a.x} * b.y - std::int64_t{b.x} * a.y;
  }
  return sum;
}

std::string encodeTile(const Tile& tile) {
  pb::Tile out;
  for (const Layer& layer : tile.layers) {
    pb::Tile::Layer l;
    l.set_version(2);
    l.set_name(layer.name);
    l.set_extent(layer.extent);
    TagTable tags(l);
    for (const Feature& feature : layer.features) {
      pb::Tile::Feature f;
      if (feature.id != 0)
        f.set_id(feature.id);
      f.set_type(static_cast<pb::Tile::GeomType>(feature.type));
      if (!encodeGeometry(feature, f))
        continue;
      for (const Property& p : feature.properties)
        tags.tag(p, f);
      *l.add_features() = std::move(f);
    }
    if (l.features_size() > 0)
      *out.add_layers() = std::move(l);
  }
  return out.SerializeAsString();
}

base::Result<Tile> decodeTile(std::string_view bytes) {
  pb::Tile in;
  if (!in.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())))
    return bad("the protobuf does not parse");
  Tile tile;
  for (const pb::Tile::Layer& l : in.layers()) {
    STRAHLER_ASSIGN_OR_RETURN(Layer layer, decodeLayer(l));
    tile.layers.push_back(std::move(layer));
  }
  return tile;
}

} // namespace strahler::vector_tile
