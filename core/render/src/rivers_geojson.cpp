#include "strahler/render/rivers_geojson.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace strahler::render {
namespace {

using nlohmann::json;

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

/// True when the edge below node i simply continues the edge below its only child.
bool continuesChild(const network::RiverNetwork& network,
                    const std::vector<primitives::RiverType>& types, std::size_t i) {
  const network::RiverNode& node = network.nodes[i];
  if (node.children.size() != 1)
    return false;
  const std::size_t c = node.children.front().index();
  return network.nodes[c].strahler == node.strahler && types[c] == types[i];
}

json section(const network::RiverNetwork& network, const std::vector<double>& flow,
             const std::vector<primitives::RiverType>& types,
             const geometry::LocalProjection& projection, std::size_t head) {
  json coordinates = json::array({lonLat(projection, network.nodes[head].position)});
  std::size_t cur = head;
  std::size_t lastUpstream = head; // upstream node of the section's last edge: its flow
  for (;;) {
    lastUpstream = cur;
    const std::size_t next = network.nodes[cur].parent.index();
    coordinates.push_back(lonLat(projection, network.nodes[next].position));
    cur = next;
    if (!network.nodes[cur].parent.valid() || !continuesChild(network, types, cur))
      break;
  }
  return {{"type", "Feature"},
          {"geometry", {{"type", "LineString"}, {"coordinates", std::move(coordinates)}}},
          {"properties",
           {{"strahler", network.nodes[head].strahler},
            {"rosgen", primitives::riverTypeName(types[head])},
            {"flow", round2(flow[lastUpstream])},
            {"elevationUp", round2(network.nodes[head].elevation)},
            {"elevationDown", round2(network.nodes[cur].elevation)},
            {"tree", network.nodes[head].tree}}}};
}

} // namespace

std::string riversGeoJson(const network::RiverNetwork& network, const std::vector<double>& flow,
                          const std::vector<primitives::RiverType>& types,
                          const geometry::LocalProjection& projection) {
  json features = json::array();
  for (std::size_t i = 0; i < network.nodes.size(); ++i) {
    if (!network.nodes[i].parent.valid() || continuesChild(network, types, i))
      continue;
    features.push_back(section(network, flow, types, projection, i));
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
           {"flow", round2(flow[m.node.index()])},
           {"onLake", m.onLake}}}});
  }
  return json{{"type", "FeatureCollection"}, {"features", std::move(features)}}.dump();
}

} // namespace strahler::render
