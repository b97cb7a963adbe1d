#include "strahler/network/network_growth.h"

#include "edge_rules.h"

#include "strahler/base/random.h"
#include "strahler/geometry/distance.h"
#include "strahler/geometry/grid_index.h"
#include "strahler/network/relief_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>
#include <string>

namespace strahler::network {
namespace {

using geometry::Vec2;

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr int kAttemptsPerChild = 4;
constexpr double kMinRise = 0.01;         // metres: children are strictly higher
constexpr double kSlopeRadiusEdges = 3.0; // κ test radius, in edge lengths
constexpr double kMaxNodes = 2'000'000.0; // memory bound on one network
constexpr std::uint64_t kGrowthStream = 0x67726f77ull;

/// A child the grammar asks for: direction relative to the parent's, and its priority.
struct ChildRequest {
  double angle = 0.0; // radians from the parent's flow direction (upstream)
  int priority = 1;
};

class Grower {
public:
  Grower(const input::WorldSpec& spec, const geometry::PolygonIndex& land)
      : params_(spec.params), land_(land), relief_(spec, land),
        rng_(spec.params.seed, kGrowthStream),
        edges_(land.bounds().expanded(spec.params.edgeLength), spec.params.sigma),
        nodeGrid_(land.bounds().expanded(spec.params.edgeLength), spec.params.edgeLength),
        heaps_(static_cast<std::size_t>(std::max(spec.params.maxPriority, 12)) + 1) {}

  RiverNetwork run(const std::vector<MouthSite>& mouths, const base::ProgressCallback& progress,
                   double landArea) {
    network_.edgeLength = params_.edgeLength;
    for (const MouthSite& m : mouths)
      addMouth(m);
    std::size_t steps = 0;
    while (candidateCount_ > 0) {
      const NodeId selected = selectCandidate();
      expand(selected);
      if (progress && (++steps & 511u) == 0) {
        const double filled = double(network_.nodes.size()) * params_.sigma * params_.edgeLength;
        progress("network", std::min(0.99, filled / landArea));
      }
    }
    computeStrahlerNumbers(network_);
    if (progress)
      progress("network", 1.0);
    return std::move(network_);
  }

private:
  using HeapEntry = std::pair<double, std::uint32_t>; // (elevation, node index)
  using MinHeap = std::priority_queue<HeapEntry, std::vector<HeapEntry>, std::greater<>>;

  void addMouth(const MouthSite& m) {
    const NodeId id = addNode(m.position, 0.0, NodeId::invalid(), m.priority, m.inward);
    network_.mouths.push_back({id, m.inward, m.onLake});
    network_.nodes[id.index()].tree = static_cast<std::uint32_t>(network_.mouths.size() - 1);
  }

  NodeId addNode(Vec2 p, double z, NodeId parent, int priority, Vec2 dir) {
    const NodeId id(static_cast<std::uint32_t>(network_.nodes.size()));
    RiverNode node;
    node.position = p;
    node.elevation = z;
    node.parent = parent;
    node.priority = std::max(1, priority);
    if (parent.valid()) {
      RiverNode& up = network_.nodes[parent.index()];
      up.children.push_back(id);
      node.tree = up.tree;
      geometry::Aabb box;
      box.add(up.position);
      box.add(p);
      edges_.insert(box, id.value);
    }
    geometry::Aabb point;
    point.add(p);
    nodeGrid_.insert(point, id.value);
    network_.nodes.push_back(node);
    directions_.push_back(dir);
    pushCandidate(id);
    return id;
  }

  void pushCandidate(NodeId id) {
    const RiverNode& n = network_.nodes[id.index()];
    const auto slot = static_cast<std::size_t>(std::min<int>(n.priority, int(heaps_.size()) - 1));
    heaps_[slot].push({n.elevation, id.value});
    ++candidateCount_;
    if (slot > 1)
      ++highPriorityCount_;
  }

  /// Section 4.2.1: lowest candidate N_l, then the highest priority within ζ of it.
  NodeId selectCandidate() {
    double lowest = std::numeric_limits<double>::infinity();
    for (const MinHeap& h : heaps_)
      if (!h.empty())
        lowest = std::min(lowest, h.top().first);
    for (std::size_t slot = heaps_.size(); slot-- > 0;) {
      MinHeap& h = heaps_[slot];
      if (h.empty() || h.top().first - lowest > params_.zeta)
        continue;
      const NodeId id(h.top().second);
      h.pop();
      --candidateCount_;
      if (slot > 1)
        --highPriorityCount_;
      return id;
    }
    STRAHLER_ASSERT(false, "a candidate always lies within zeta of the lowest one");
  }

  double jitter() { return rng_.uniform(-1.0, 1.0) * params_.angleJitter * kDegree; }

  /// Rule 1 (fill): fillBranches children of priority 1. The first prolongs the river; a
  /// second branches off like rule 2.2's side branch, so confluences stay binary. (The paper's
  /// fan of p ∈ [1, 5] children over ±80° made confluences of 3 to 5 inflows, and a fan of 4
  /// or 5 ended the river, as each child lay closer than σ to its siblings' edges.)
  std::vector<ChildRequest> fillChildren() {
    if (params_.fillBranches < 2)
      return {{0.0, 1}};
    const double branch = params_.branchAngle * kDegree;
    const double side = rng_.chance(0.5) ? 1.0 : -1.0;
    return {{-side * 0.15 * branch, 1}, {side * branch, 1}};
  }

  /// The grammar of Figure 7: which children N_X asks for.
  std::vector<ChildRequest> applyRules(int n) {
    const double branch = params_.branchAngle * kDegree;
    if (n <= 1 && highPriorityCount_ == 0)
      return fillChildren();
    const double u = rng_.uniform();
    if (u < params_.probContinue)
      return {{0.0, n}}; // rule 2.1
    const double side = rng_.chance(0.5) ? 1.0 : -1.0;
    if (u < params_.probContinue + params_.probAsymmetric) { // rule 2.2
      const int m = n > 1 ? 1 + static_cast<int>(rng_.below(static_cast<std::uint32_t>(n - 1))) : 1;
      return {{-side * 0.15 * branch, n}, {side * branch, m}};
    }
    const int k = std::max(1, n - 1); // rule 2.3
    return {{-0.5 * branch, k}, {0.5 * branch, k}};
  }

  void expand(NodeId id) {
    const int n = network_.nodes[id.index()].priority;
    for (const ChildRequest& child : applyRules(n))
      tryChild(id, child);
  }

  void tryChild(NodeId parentId, const ChildRequest& child) {
    const Vec2 dir = directions_[parentId.index()];
    const double baseAngle = std::atan2(dir.y, dir.x) + child.angle;
    for (int attempt = 0; attempt < kAttemptsPerChild; ++attempt) {
      const RiverNode& parent = network_.nodes[parentId.index()];
      const Vec2 step = geometry::direction(baseAngle + jitter() * (1.0 + attempt));
      const Vec2 p = parent.position + step * params_.edgeLength;
      const double rise = params_.edgeLength * relief_.riverSlope(p) *
                          (1.0 + params_.slopeJitter * rng_.uniform(-1.0, 1.0));
      const double z = parent.elevation + std::max(rise, kMinRise);
      if (valid(parentId, p, z)) {
        addNode(p, z, parentId, child.priority, step);
        return;
      }
    }
  }

  /// The geometric tests of Section 4.2.2 for a new node p (elevation z) below `parentId`.
  bool valid(NodeId parentId, Vec2 p, double z) const {
    const RiverNode& parent = network_.nodes[parentId.index()];
    const bool fromMouth = !parent.parent.valid();
    if (fromMouth ? !detail::mouthEdgeValid(land_, parent.position, p, params_.delta)
                  : !detail::innerEdgeValid(land_, parent.position, p, params_.delta))
      return false;
    return clearOfOtherEdges(parentId, p) && slopesBelowKappa(p, z);
  }

  bool clearOfOtherEdges(NodeId parentId, Vec2 p) const {
    const RiverNode& parent = network_.nodes[parentId.index()];
    geometry::Aabb box;
    box.add(parent.position);
    box.add(p);
    return edges_.query(box.expanded(params_.sigma), [&](std::uint32_t c) {
      const RiverNode& other = network_.nodes[c];
      // Edges sharing the parent node are adjacent: the parent's own edge and its siblings'.
      if (c == parentId.value || other.parent == parentId)
        return true;
      const Vec2 a = network_.nodes[other.parent.index()].position;
      return geometry::segmentSegmentDistance(parent.position, p, a, other.position) >
             params_.sigma;
    });
  }

  bool slopesBelowKappa(Vec2 p, double z) const {
    const double radius = kSlopeRadiusEdges * params_.edgeLength;
    geometry::Aabb box;
    box.add(p);
    return nodeGrid_.query(box.expanded(radius), [&](std::uint32_t i) {
      const RiverNode& other = network_.nodes[i];
      const double d = distance(other.position, p);
      return d > radius || std::abs(z - other.elevation) < params_.kappa * d;
    });
  }

  const input::Params& params_;
  const geometry::PolygonIndex& land_;
  ReliefLaw relief_;
  base::Rng rng_;
  geometry::GridIndex edges_;    // edge [parent(c), c] registered under child id c
  geometry::GridIndex nodeGrid_; // every node
  std::vector<MinHeap> heaps_;   // candidates X by priority
  std::size_t candidateCount_ = 0;
  std::size_t highPriorityCount_ = 0; // candidates with priority > 1
  std::vector<Vec2> directions_;      // per node: unit flow direction, upstream
  RiverNetwork network_;
};

/// Refuses worlds whose network would not fit the memory bound.
base::Status checkNodeBudget(const input::WorldSpec& spec, double landArea) {
  const double expectedNodes = landArea / (spec.params.sigma * spec.params.edgeLength);
  if (expectedNodes <= kMaxNodes)
    return base::Ok{};
  return base::makeError(
      base::ErrorCode::kLimitExceeded,
      "this world would have about " + std::to_string(static_cast<long long>(expectedNodes)) +
          " river nodes, more than the limit of 2000000: raise edgeLength or sigma");
}

} // namespace

base::Result<RiverNetwork> growNetwork(const input::WorldSpec& spec,
                                       const geometry::PolygonIndex& land,
                                       const std::vector<MouthSite>& mouths,
                                       const base::ProgressCallback& progress) {
  const double landArea = geometry::area(land.polygons());
  STRAHLER_RETURN_IF_ERROR(checkNodeBudget(spec, landArea));
  Grower grower(spec, land);
  return grower.run(mouths, progress, std::max(landArea, 1.0));
}

base::Result<RiverNetwork> generateNetwork(const input::WorldSpec& spec,
                                           const geometry::PolygonIndex& land,
                                           const base::ProgressCallback& progress) {
  STRAHLER_RETURN_IF_ERROR(checkNodeBudget(spec, geometry::area(land.polygons())));
  STRAHLER_ASSIGN_OR_RETURN(std::vector<MouthSite> mouths, placeMouths(spec, land));
  return growNetwork(spec, land, mouths, progress);
}

} // namespace strahler::network
