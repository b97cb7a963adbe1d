#include "strahler/render/rivers_geojson.h"

#include "strahler/geometry/polyline_simplify.h"
#include "strahler/primitives/river_primitive.h"
#include "strahler/render/river_sections.h"

#include <charconv>
#include <cmath>
#include <string_view>
#include <utility>
#include <vector>

namespace strahler::render {
namespace {

double round6(double v) {
  return std::round(v * 1e6) / 1e6;
}
double round2(double v) {
  return std::round(v * 100.0) / 100.0;
}

/// Appends JSON text to a string: numbers by std::to_chars (shortest round trip), no DOM, so
/// a large world's 50 MB of lines cost a pass over the data, not a tree of small allocations.
class JsonWriter {
public:
  explicit JsonWriter(std::string& out) : out_(out) {}

  JsonWriter& raw(std::string_view text) {
    out_.append(text);
    return *this;
  }
  JsonWriter& number(double v) {
    if (!std::isfinite(v))
      return raw("null");
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    out_.append(buffer, end);
    return *this;
  }
  JsonWriter& integer(long long v) {
    char buffer[24];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    out_.append(buffer, end);
    return *this;
  }
  /// A key and its colon; `key` needs no escaping.
  JsonWriter& key(std::string_view name) {
    out_.push_back('"');
    out_.append(name);
    return raw("\":");
  }
  /// A string value without characters that need escaping (names of this module).
  JsonWriter& plain(std::string_view text) {
    out_.push_back('"');
    out_.append(text);
    out_.push_back('"');
    return *this;
  }
  JsonWriter& lonLat(const geometry::LocalProjection& projection, geometry::Vec2 p) {
    const geometry::Vec2 ll = projection.inverse(p);
    raw("[").number(round6(ll.x)).raw(",").number(round6(ll.y)).raw("]");
    return *this;
  }

private:
  std::string& out_;
};

} // namespace

std::string riversGeoJson(const construction::WorldData& world,
                          const geometry::LocalProjection& projection) {
  const network::RiverNetwork& network = world.network;
  std::string text;
  JsonWriter out(text);
  out.raw("{\"features\":[");
  bool first = true;
  forEachRiverSection(world, [&](const RiverSection& s) {
    if (!std::exchange(first, false))
      out.raw(",");
    out.raw("{\"geometry\":{\"coordinates\":[");
    bool firstPoint = true;
    for (std::size_t k : geometry::simplifyPolyline(s.line, kRiverLineTolerance)) {
      if (!std::exchange(firstPoint, false))
        out.raw(",");
      out.lonLat(projection, s.line[k]);
    }
    out.raw("],\"type\":\"LineString\"},\"properties\":{");
    out.key("elevationDown").number(round2(s.elevationDown));
    out.raw(",").key("elevationUp").number(round2(s.elevationUp));
    out.raw(",").key("flow").number(round2(s.flow));
    out.raw(",").key("rosgen").plain(primitives::riverTypeName(s.rosgen));
    out.raw(",").key("strahler").integer(s.strahler);
    out.raw(",").key("tree").integer(s.tree);
    out.raw(",").key("widthDownM").number(round2(s.widthDown));
    out.raw(",").key("widthUpM").number(round2(s.widthUp));
    out.raw("},\"type\":\"Feature\"}");
  });
  for (const network::Mouth& m : network.mouths) {
    const network::RiverNode& node = network.node(m.node);
    if (!std::exchange(first, false))
      out.raw(",");
    out.raw("{\"geometry\":{\"coordinates\":").lonLat(projection, node.position);
    out.raw(",\"type\":\"Point\"},\"properties\":{");
    out.key("flow").number(round2(world.flow[m.node.index()]));
    out.raw(",").key("mouth").raw("true");
    out.raw(",").key("onLake").raw(m.onLake ? "true" : "false");
    out.raw(",").key("priority").integer(node.priority);
    out.raw(",").key("strahler").integer(node.strahler);
    out.raw("},\"type\":\"Feature\"}");
  }
  out.raw("],\"type\":\"FeatureCollection\"}");
  return text;
}

} // namespace strahler::render
