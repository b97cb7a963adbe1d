#include "strahler/render/rivers_geojson.h"

#include "strahler/geometry/polyline_simplify.h"
#include "strahler/primitives/river_primitives.h"

#include <charconv>
#include <cmath>
#include <string_view>
#include <utility>
#include <vector>

namespace strahler::render {
namespace {

using primitives::RiverPrimitive;
using primitives::RiverType;

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

/// The river primitive of each node's downstream section (null for mouths).
std::vector<const RiverPrimitive*> primitiveOfNode(const construction::WorldData& world) {
  std::vector<const RiverPrimitive*> byNode(world.network.nodes.size(), nullptr);
  for (const RiverPrimitive& r : world.rivers)
    if (r.node.valid() && r.node.index() < byNode.size())
      byNode[r.node.index()] = &r;
  return byNode;
}

/// True when the edge below node i simply continues the edge below its only child.
bool continuesChild(const network::RiverNetwork& network, const std::vector<RiverType>& types,
                    std::size_t i) {
  const network::RiverNode& node = network.nodes[i];
  if (node.children.size() != 1)
    return false;
  const std::size_t c = node.children.front().index();
  return network.nodes[c].strahler == node.strahler && types[c] == types[i];
}

/// Appends the line of the edge below node i: its primitive's curve, else the straight edge.
/// The first point (the node, already the end of the previous edge) is left out.
void appendEdge(const network::RiverNetwork& network, const RiverPrimitive* river, std::size_t i,
                std::vector<geometry::Vec2>& line) {
  const geometry::Vec2 down = network.nodes[network.nodes[i].parent.index()].position;
  if (river == nullptr || river->curve.size() < 2) {
    line.push_back(down);
    return;
  }
  for (std::size_t k = 1; k < river->curve.size(); ++k)
    line.push_back(river->curve[k].position);
}

class SectionWriter {
public:
  SectionWriter(const construction::WorldData& world, const geometry::LocalProjection& projection)
      : world_(world), net_(world.network), projection_(projection),
        byNode_(primitiveOfNode(world)) {}

  /// Appends the Feature of the section whose first edge is below node `head`.
  void section(std::size_t head, JsonWriter& out) {
    line_.assign(1, net_.nodes[head].position);
    std::size_t cur = head;
    std::size_t lastUpstream = head; // upstream node of the section's last edge: its flow
    for (;;) {
      lastUpstream = cur;
      appendEdge(net_, byNode_[cur], cur, line_);
      cur = net_.nodes[cur].parent.index();
      if (!net_.nodes[cur].parent.valid() || !continuesChild(net_, world_.riverTypes, cur))
        break;
    }
    out.raw("{\"geometry\":{\"coordinates\":[");
    bool first = true;
    for (std::size_t k : geometry::simplifyPolyline(line_, kRiverLineTolerance)) {
      if (!std::exchange(first, false))
        out.raw(",");
      out.lonLat(projection_, line_[k]);
    }
    const network::RiverNode& top = net_.nodes[head];
    out.raw("],\"type\":\"LineString\"},\"properties\":{");
    out.key("elevationDown").number(round2(net_.nodes[cur].elevation));
    out.raw(",").key("elevationUp").number(round2(top.elevation));
    out.raw(",").key("flow").number(round2(world_.flow[lastUpstream]));
    out.raw(",").key("rosgen").plain(primitives::riverTypeName(world_.riverTypes[head]));
    out.raw(",").key("strahler").integer(top.strahler);
    out.raw(",").key("tree").integer(top.tree);
    out.raw(",").key("widthDownM").number(round2(widthDown(lastUpstream)));
    out.raw(",").key("widthUpM").number(round2(widthUp(head)));
    out.raw("},\"type\":\"Feature\"}");
  }

private:
  double widthUp(std::size_t i) const {
    const RiverPrimitive* r = byNode_[i];
    return r ? r->widthUp : primitives::channelWidth(world_.flow[i]);
  }
  double widthDown(std::size_t i) const {
    const RiverPrimitive* r = byNode_[i];
    return r ? r->widthDown : primitives::channelWidth(world_.flow[net_.nodes[i].parent.index()]);
  }

  const construction::WorldData& world_;
  const network::RiverNetwork& net_;
  const geometry::LocalProjection& projection_;
  std::vector<const RiverPrimitive*> byNode_;
  std::vector<geometry::Vec2> line_; // the section being written
};

} // namespace

std::string riversGeoJson(const construction::WorldData& world,
                          const geometry::LocalProjection& projection) {
  const network::RiverNetwork& network = world.network;
  SectionWriter writer(world, projection);
  std::string text;
  JsonWriter out(text);
  out.raw("{\"features\":[");
  bool first = true;
  for (std::size_t i = 0; i < network.nodes.size(); ++i) {
    if (!network.nodes[i].parent.valid() || continuesChild(network, world.riverTypes, i))
      continue;
    if (!std::exchange(first, false))
      out.raw(",");
    writer.section(i, out);
  }
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
