#include "strahler/analysis/river_profiles.h"

#include "strahler/network/relief_law.h"

#include <algorithm>
#include <cmath>

namespace strahler::analysis {
namespace {
constexpr double kSquareMetresPerKm2 = 1e6;
constexpr double kMinRise = 0.01; // m: every child strictly above its parent
} // namespace

std::vector<double> drainageAreasKm2(const network::RiverNetwork& network,
                                     const blocks::BlockSet& blocks) {
  const std::size_t n = network.nodes.size();
  std::vector<double> area(n, 0.0);
  // Children come after their parent: a reverse sweep adds each subtree before its root.
  for (std::size_t i = n; i-- > 0;) {
    area[i] += blocks.blocks[i].area / kSquareMetresPerKm2;
    const network::NodeId parent = network.nodes[i].parent;
    if (parent.valid())
      area[parent.index()] += area[i];
  }
  return area;
}

void shapeRiverProfiles(const input::WorldSpec& spec, const geometry::PolygonIndex& land,
                        const blocks::BlockSet& blocks, network::RiverNetwork& network) {
  const input::Params& params = spec.params;
  const std::vector<double> area = drainageAreasKm2(network, blocks);
  const network::ReliefLaw relief(spec, land);
  // Parents come before their children: a forward sweep sets each node from a final parent.
  for (std::size_t i = 0; i < network.nodes.size(); ++i) {
    network::RiverNode& node = network.nodes[i];
    if (!node.parent.valid())
      continue;
    const network::RiverNode& parent = network.node(node.parent);
    const double length = distance(node.position, parent.position);
    const double slope =
        relief.riverSlope(lerp(node.position, parent.position, 0.5)) *
        std::pow(std::max(area[i], 1e-6) / params.referenceArea, -params.concavity);
    node.elevation = parent.elevation + std::max(length * slope, kMinRise);
  }
}

} // namespace strahler::analysis
