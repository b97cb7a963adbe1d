#include "strahler/quality/horton.h"

#include "line_fit.h"

#include "strahler/base/assert.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strahler::quality {
namespace {

using network::NodeId;
using network::RiverNetwork;
using network::RiverNode;

/// True if no child of `node` has its Strahler number, so a stream starts at its edge.
bool startsStream(const RiverNetwork& net, const RiverNode& node) {
  return std::none_of(node.children.begin(), node.children.end(),
                      [&](NodeId c) { return net.node(c).strahler == node.strahler; });
}

/// Length in metres of the stream whose first (most upstream) edge leaves `head`.
double streamLength(const RiverNetwork& net, const RiverNode& head) {
  double length = 0.0;
  const RiverNode* node = &head;
  while (node->parent.valid() && node->strahler == head.strahler) {
    const RiverNode& parent = net.node(node->parent);
    length += geometry::distance(node->position, parent.position);
    node = &parent;
  }
  return length;
}

/// Fills the two ratios from the per-order counts and mean lengths.
void fitRatios(HortonStatistics& stats) {
  std::vector<double> order, logCount, logLength;
  for (std::size_t k = 1; k < stats.streamCount.size(); ++k) {
    if (stats.streamCount[k] == 0)
      continue;
    order.push_back(double(k));
    logCount.push_back(std::log(double(stats.streamCount[k])));
    logLength.push_back(std::log(stats.meanStreamLength[k]));
  }
  stats.bifurcationRatio = std::exp(-detail::fitLine(order, logCount).slope);
  stats.lengthRatio = std::exp(detail::fitLine(order, logLength).slope);
  stats.fractalDimension = stats.lengthRatio > 1.0
                               ? std::log(stats.bifurcationRatio) / std::log(stats.lengthRatio)
                               : std::numeric_limits<double>::quiet_NaN();
}

} // namespace

HortonStatistics hortonStatistics(const RiverNetwork& network) {
  HortonStatistics stats;
  stats.streamCount.assign(1, 0);
  stats.meanStreamLength.assign(1, 0.0);
  for (const RiverNode& node : network.nodes) {
    if (!node.parent.valid() || !startsStream(network, node))
      continue;
    STRAHLER_ASSERT(node.strahler >= 1, "Strahler numbers not computed");
    const auto k = static_cast<std::size_t>(node.strahler);
    if (stats.streamCount.size() <= k) {
      stats.streamCount.resize(k + 1, 0);
      stats.meanStreamLength.resize(k + 1, 0.0);
    }
    ++stats.streamCount[k];
    stats.meanStreamLength[k] += streamLength(network, node);
  }
  for (std::size_t k = 1; k < stats.streamCount.size(); ++k) {
    if (stats.streamCount[k] > 0)
      stats.meanStreamLength[k] /= double(stats.streamCount[k]);
  }
  fitRatios(stats);
  return stats;
}

} // namespace strahler::quality
