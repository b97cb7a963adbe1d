#include "strahler/network/river_network.h"

#include <algorithm>

namespace strahler::network {

double RiverNetwork::totalLength() const noexcept {
  double total = 0.0;
  for (const RiverNode& n : nodes)
    if (n.parent.valid())
      total += geometry::distance(n.position, node(n.parent).position);
  return total;
}

void computeStrahlerNumbers(RiverNetwork& network) {
  // Children always come after their parent, so a reverse sweep sees children first.
  for (std::size_t i = network.nodes.size(); i-- > 0;) {
    RiverNode& n = network.nodes[i];
    int highest = 0, countHighest = 0;
    for (NodeId c : n.children) {
      const int s = network.nodes[c.index()].strahler;
      if (s > highest) {
        highest = s;
        countHighest = 1;
      } else if (s == highest) {
        ++countHighest;
      }
    }
    n.strahler = highest == 0 ? 1 : (countHighest > 1 ? highest + 1 : highest);
  }
}

std::vector<std::size_t> strahlerHistogram(const RiverNetwork& network) {
  std::vector<std::size_t> histogram(2, 0);
  for (const RiverNode& n : network.nodes) {
    const auto s = static_cast<std::size_t>(std::max(1, n.strahler));
    if (histogram.size() <= s)
      histogram.resize(s + 1, 0);
    ++histogram[s];
  }
  return histogram;
}

} // namespace strahler::network
