#include "strahler/analysis/network_analysis.h"

#include "strahler/analysis/river_profiles.h"
#include "strahler/network/relief_law.h"

#include <algorithm>
#include <cmath>

namespace strahler::analysis {
namespace {

void accumulateDrainage(const network::RiverNetwork& network, const blocks::BlockSet& blocks,
                        NetworkAnalysis& out) {
  const std::size_t n = network.nodes.size();
  out.drainageAreaKm2 = drainageAreasKm2(network, blocks);
  out.flow.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    out.flow[i] = flowFromArea(out.drainageAreaKm2[i]);
  out.watershedAreaKm2.clear();
  for (const network::Mouth& m : network.mouths)
    out.watershedAreaKm2.push_back(out.drainageAreaKm2[m.node.index()]);
}

void measureRiverDistances(const network::RiverNetwork& network, NetworkAnalysis& out) {
  out.distanceToMouth.assign(network.nodes.size(), 0.0);
  for (std::size_t i = 0; i < network.nodes.size(); ++i) {
    const network::RiverNode& node = network.nodes[i];
    if (!node.parent.valid())
      continue;
    out.distanceToMouth[i] = out.distanceToMouth[node.parent.index()] +
                             distance(node.position, network.node(node.parent).position);
  }
}

RosgenType classify(const input::Params& params, const network::RiverNetwork& network,
                    const NetworkAnalysis& analysis, std::size_t i) {
  const network::RiverNode& node = network.nodes[i];
  const double flow = analysis.flow[i];
  if (!node.parent.valid() && flow >= params.deltaMinFlow)
    return RosgenType::kDelta;
  if (analysis.distanceToMouth[i] <= params.braidedMaxDistance && flow >= params.braidedMinFlow)
    return RosgenType::kBraided;
  if (!node.parent.valid())
    return RosgenType::kSinuous;
  const network::RiverNode& down = network.node(node.parent);
  const double slope =
      (node.elevation - down.elevation) / std::max(distance(node.position, down.position), 1e-9);
  return slope >= params.straightMinSlope ? RosgenType::kStraight : RosgenType::kSinuous;
}

} // namespace

const char* rosgenName(RosgenType type) noexcept {
  switch (type) {
  case RosgenType::kStraight:
    return "B";
  case RosgenType::kSinuous:
    return "E";
  case RosgenType::kBraided:
    return "D";
  case RosgenType::kDelta:
    return "D-delta";
  }
  return "?";
}

double flowFromArea(double areaKm2) noexcept {
  return 0.42 * std::pow(std::max(areaKm2, 0.0), 0.69);
}

NetworkAnalysis analyzeNetwork(const input::WorldSpec& spec, const geometry::PolygonIndex& land,
                               const network::RiverNetwork& network,
                               const blocks::BlockSet& blocks) {
  NetworkAnalysis out;
  accumulateDrainage(network, blocks, out);
  measureRiverDistances(network, out);
  out.rosgen.resize(network.nodes.size());
  for (std::size_t i = 0; i < network.nodes.size(); ++i)
    out.rosgen[i] = classify(spec.params, network, out, i);

  const network::ReliefLaw relief(spec, land);
  out.ridgeElevation.resize(blocks.vertices.size());
  for (std::size_t v = 0; v < blocks.vertices.size(); ++v) {
    const blocks::VoronoiVertex& q = blocks.vertices[v];
    double highest = 0.0;
    for (network::NodeId site : q.sites)
      highest = std::max(highest, network.node(site).elevation);
    // Over the sea (hull vertices can lie tens of km out) ridges do not keep rising.
    const double reach =
        land.contains(q.position) ? q.radius : std::min(q.radius, spec.params.edgeLength);
    out.ridgeElevation[v] = highest + relief.ridgeLambda(q.position) * reach;
  }
  return out;
}

} // namespace strahler::analysis
