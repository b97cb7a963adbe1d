#include "strahler/render/river_sections.h"

#include "strahler/primitives/river_primitives.h"

namespace strahler::render {
namespace {

using primitives::RiverPrimitive;
using primitives::RiverType;

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

} // namespace

void forEachRiverSection(const construction::WorldData& world,
                         const std::function<void(const RiverSection&)>& visit) {
  const network::RiverNetwork& net = world.network;
  const std::vector<const RiverPrimitive*> byNode = primitiveOfNode(world);
  RiverSection s;
  for (std::size_t head = 0; head < net.nodes.size(); ++head) {
    if (!net.nodes[head].parent.valid() || continuesChild(net, world.riverTypes, head))
      continue;
    s.line.assign(1, net.nodes[head].position);
    std::size_t cur = head;
    std::size_t lastUpstream = head; // upstream node of the section's last edge: its flow
    for (;;) {
      lastUpstream = cur;
      appendEdge(net, byNode[cur], cur, s.line);
      cur = net.nodes[cur].parent.index();
      if (!net.nodes[cur].parent.valid() || !continuesChild(net, world.riverTypes, cur))
        break;
    }
    const network::RiverNode& top = net.nodes[head];
    s.strahler = top.strahler;
    s.tree = top.tree;
    s.rosgen = world.riverTypes[head];
    s.flow = world.flow[lastUpstream];
    const RiverPrimitive* up = byNode[head];
    s.widthUp = up ? up->widthUp : primitives::channelWidth(world.flow[head]);
    const RiverPrimitive* down = byNode[lastUpstream];
    s.widthDown =
        down ? down->widthDown
             : primitives::channelWidth(world.flow[net.nodes[lastUpstream].parent.index()]);
    s.elevationUp = top.elevation;
    s.elevationDown = net.nodes[cur].elevation;
    visit(s);
  }
}

} // namespace strahler::render
