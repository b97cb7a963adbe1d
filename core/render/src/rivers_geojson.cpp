#include "strahler/render/rivers_geojson.h"

#include "strahler/geometry/polyline_simplify.h"
#include "strahler/primitives/river_primitives.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace strahler::render {
namespace {

using nlohmann::json;
using primitives::RiverPrimitive;
using primitives::RiverType;

double round6(double v) {
  return std::round(v * 1e6) / 1e6;
}
double round2(double v) {
  return std::round(v * 100.0) / 100.0;
}

json lonLat(const geometry::LocalProjection& projection, geometry::Vec2 p) {
  const geometry::Vec2 ll = projection.inverse(p);
  return json::array({round6(ll.x), round6(ll.y)});
}

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

  json section(std::size_t head) const {
    std::vector<geometry::Vec2> line{net_.nodes[head].position};
    std::size_t cur = head;
    std::size_t lastUpstream = head; // upstream node of the section's last edge: its flow
    for (;;) {
      lastUpstream = cur;
      appendEdge(net_, byNode_[cur], cur, line);
      cur = net_.nodes[cur].parent.index();
      if (!net_.nodes[cur].parent.valid() || !continuesChild(net_, world_.riverTypes, cur))
        break;
    }
    json coordinates = json::array();
    for (std::size_t k : geometry::simplifyPolyline(line, kRiverLineTolerance))
      coordinates.push_back(lonLat(projection_, line[k]));
    const network::RiverNode& top = net_.nodes[head];
    return {{"type", "Feature"},
            {"geometry", {{"type", "LineString"}, {"coordinates", std::move(coordinates)}}},
            {"properties",
             {{"strahler", top.strahler},
              {"rosgen", primitives::riverTypeName(world_.riverTypes[head])},
              {"flow", round2(world_.flow[lastUpstream])},
              {"widthUpM", round2(widthUp(head))},
              {"widthDownM", round2(widthDown(lastUpstream))},
              {"elevationUp", round2(top.elevation)},
              {"elevationDown", round2(net_.nodes[cur].elevation)},
              {"tree", top.tree}}}};
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
};

} // namespace

std::string riversGeoJson(const construction::WorldData& world,
                          const geometry::LocalProjection& projection) {
  const network::RiverNetwork& network = world.network;
  const SectionWriter writer(world, projection);
  json features = json::array();
  for (std::size_t i = 0; i < network.nodes.size(); ++i) {
    if (!network.nodes[i].parent.valid() || continuesChild(network, world.riverTypes, i))
      continue;
    features.push_back(writer.section(i));
  }
  for (const network::Mouth& m : network.mouths) {
    const network::RiverNode& node = network.node(m.node);
    features.push_back(
        {{"type", "Feature"},
         {"geometry", {{"type", "Point"}, {"coordinates", lonLat(projection, node.position)}}},
         {"properties",
          {{"mouth", true},
           {"priority", node.priority},
           {"strahler", node.strahler},
           {"flow", round2(world.flow[m.node.index()])},
           {"onLake", m.onLake}}}});
  }
  return json{{"type", "FeatureCollection"}, {"features", std::move(features)}}.dump();
}

} // namespace strahler::render
