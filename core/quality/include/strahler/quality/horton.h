#pragma once

#include "strahler/network/river_network.h"

#include <cstddef>
#include <vector>

namespace strahler::quality {

/// Horton's laws of stream numbers and lengths for one river network.
struct HortonStatistics {
  /// streamCount[k] = N_k, the number of streams of order k; index 0 unused (0). Size is
  /// 1 + the highest order of any edge (1 for a network without edges).
  std::vector<std::size_t> streamCount;
  /// meanStreamLength[k] = mean length of the streams of order k, metres; index 0 unused (0).
  std::vector<double> meanStreamLength;
  /// Rb = exp(-slope) of the least-squares line of ln N_k against k; NaN with < 2 orders.
  double bifurcationRatio = 0.0;
  /// Rl = exp(slope) of the least-squares line of ln mean length against k; NaN with < 2 orders.
  double lengthRatio = 0.0;
  /// The network's fractal dimension as seed 001 (after Masek & Turcotte) defines it from the
  /// mean stream length against order: D = ln Rb / ln Rl; NaN when Rl <= 1 or undefined.
  double fractalDimension = 0.0;
};

/// Horton statistics of `network`, whose Strahler numbers must be up to date
/// (network::computeStrahlerNumbers). The edge node -> parent has order strahler(node); a
/// stream of order k is a maximal chain of consecutive edges of order k (a node has at most one
/// child of its own order, so streams never branch). Stream length is the sum of its edges'
/// lengths (distance between node positions). The regressions use every order with N_k >= 1.
HortonStatistics hortonStatistics(const network::RiverNetwork& network);

} // namespace strahler::quality
