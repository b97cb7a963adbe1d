#pragma once

#include "strahler/blocks/block_set.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/input/world_spec.h"
#include "strahler/network/river_network.h"

#include <cstdint>
#include <vector>

namespace strahler::analysis {

/// The river types of Section 5.2 (a subset of Rosgen's classification).
enum class RosgenType : std::uint8_t {
  kStraight = 0, ///< B: steep, nearly straight.
  kSinuous = 1,  ///< E: gentle, meandering.
  kBraided = 2,  ///< D: braided, near the coast with enough flow.
  kDelta = 3,    ///< D: delta, at a mouth with enough flow.
};

/// Short name of a type: "B", "E", "D" or "D-delta".
const char* rosgenName(RosgenType type) noexcept;

/// Hydrology of a network and its blocks (Section 5).
struct NetworkAnalysis {
  std::vector<double> drainageAreaKm2; ///< Per node: its block plus every block upstream.
  std::vector<double> flow;            ///< Per node: φ = 0.42 · A^0.69, m³/s.
  std::vector<double> distanceToMouth; ///< Per node: length along the river to its mouth, m.
  std::vector<RosgenType> rosgen;      ///< Per node: type of the section from it downstream.
  /// Per Voronoi vertex: q_z = max(p_z) + λ(q) · d (d capped at e for vertices off the land).
  std::vector<double> ridgeElevation;
  std::vector<double> watershedAreaKm2; ///< Per mouth (tree): area of its whole basin.
};

/// Mean flow (m³/s) of a river draining `areaKm2` (Dunne & Leopold): 0.42 · A^0.69.
double flowFromArea(double areaKm2) noexcept;

/// Computes watersheds, flow, ridge elevations and Rosgen types. `blocks` must have been
/// built from `network`, `land` from `spec`.
NetworkAnalysis analyzeNetwork(const input::WorldSpec& spec, const geometry::PolygonIndex& land,
                               const network::RiverNetwork& network,
                               const blocks::BlockSet& blocks);

} // namespace strahler::analysis
