#include "strahler/quality/hack_law.h"

#include "line_fit.h"

#include "strahler/analysis/river_profiles.h"
#include "strahler/blocks/block_set.h"

#include <algorithm>
#include <cmath>

namespace strahler::quality {
namespace {

/// Least-squares fit of y = a + h·x over (log10 A, log10 L) points.
HackFit fitLogLog(const std::vector<double>& x, const std::vector<double>& y) {
  HackFit fit;
  fit.points = x.size();
  const detail::LineFit line = detail::fitLine(x, y);
  if (std::isnan(line.slope))
    return fit;
  fit.exponent = line.slope;
  fit.coefficient = std::pow(10.0, line.intercept);
  fit.r2 = line.r2;
  return fit;
}

} // namespace

std::vector<double> mainStreamLengthsM(const network::RiverNetwork& network) {
  std::vector<double> length(network.nodes.size(), 0.0);
  // Children come after their parent: a reverse sweep finishes each node before its parent.
  for (std::size_t i = network.nodes.size(); i-- > 0;) {
    const network::RiverNode& node = network.nodes[i];
    if (!node.parent.valid())
      continue;
    const std::size_t p = node.parent.index();
    length[p] = std::max(length[p],
                         length[i] + geometry::distance(node.position, network.nodes[p].position));
  }
  return length;
}

HackLaw fitHackLaw(const network::RiverNetwork& network, const std::vector<double>& areaKm2) {
  const std::vector<double> length = mainStreamLengthsM(network);
  std::vector<double> x, y, mouthX, mouthY;
  for (std::size_t i = 0; i < network.nodes.size() && i < areaKm2.size(); ++i) {
    if (length[i] <= 0.0 || !(areaKm2[i] > 0.0))
      continue;
    x.push_back(std::log10(areaKm2[i]));
    y.push_back(std::log10(length[i] * 1e-3));
    if (!network.nodes[i].parent.valid()) {
      mouthX.push_back(x.back());
      mouthY.push_back(y.back());
    }
  }
  return {fitLogLog(x, y), fitLogLog(mouthX, mouthY)};
}

std::vector<double> networkDrainageAreasKm2(const construction::World& world) {
  auto blocks = blocks::buildBlocks(world.data().network, world.land());
  if (!blocks)
    return {};
  return analysis::drainageAreasKm2(world.data().network, blocks.value());
}

} // namespace strahler::quality
