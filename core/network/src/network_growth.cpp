#include "strahler/network/network_growth.h"

#include "growing_network.h"

#include "strahler/base/random.h"
#include "strahler/geometry/distance.h"
#include "strahler/geometry/distance_transform.h"
#include "strahler/geometry/grid_index.h"
#include "strahler/network/dla_growth.h"
#include "strahler/network/drawn_rivers.h"
#include "strahler/network/relief_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <queue>
#include <string>

namespace strahler::network {
namespace {

using detail::kMinRise;
using geometry::Vec2;

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr int kAttemptsPerChild = 4;
constexpr double kMaxNodes = 2'000'000.0; // memory bound on one network
constexpr std::uint64_t kGrowthStream = 0x67726f77ull;
/// Coverage (issue 16): land farther than this from every river edge is a gap that growth
/// goes back to (3 km is the target; the margin covers the carved curves, which leave the
/// edges by up to a few hundred metres, and the grid's resolution).
constexpr double kCoverageGap = 2400.0;
/// Cell side of the coverage grid, m (a coarser one on very large worlds).
constexpr double kCoverageCell = 300.0;
constexpr std::size_t kMaxCoverageCells = std::size_t{1} << 24;
/// Rounds of gap filling (each seeds every gap, then grows until no candidate is left).
constexpr int kGapRounds = 4;
/// Nodes tried per gap: the nearest ones that can take another child.
constexpr int kNodesPerGap = 12;
/// Shore sites tried per gap: the nearest ones.
constexpr int kShoreSitesPerGap = 6;

/// A child the grammar asks for: direction relative to the parent's, and its priority.
struct ChildRequest {
  double angle = 0.0; // radians from the parent's flow direction (upstream)
  int priority = 1;
};

class Grower : private detail::GrowingNetwork {
public:
  Grower(const input::WorldSpec& spec, const geometry::PolygonIndex& land)
      : GrowingNetwork(spec, land), rng_(spec.params.seed, kGrowthStream),
        heaps_(static_cast<std::size_t>(std::max(spec.params.maxPriority, 12)) + 1) {}

  RiverNetwork run(const std::vector<MouthSite>& mouths, const base::ProgressCallback& progress,
                   double landArea) {
    for (const MouthSite& m : mouths)
      addMouth(m, m.priority);
    for (std::size_t i = 0; i < mouths.size(); ++i)
      if (mouths[i].drawnRiver >= 0)
        addChain(network_.mouths[i].node, mouths[i].drawnRiver, params_.maxPriority);
    growAll(progress, landArea);
    for (int round = 0; round < kGapRounds && seedGaps() > 0; ++round)
      growAll(progress, landArea);
    computeStrahlerNumbers(network_);
    if (progress)
      progress("network", 1.0);
    return std::move(network_);
  }

private:
  using HeapEntry = std::pair<double, std::uint32_t>; // (elevation, node index)
  using MinHeap = std::priority_queue<HeapEntry, std::vector<HeapEntry>, std::greater<>>;

  /// Expands candidates until none is left.
  void growAll(const base::ProgressCallback& progress, double landArea) {
    std::size_t steps = 0;
    while (candidateCount_ > 0) {
      const NodeId selected = selectCandidate();
      expand(selected);
      if (progress && (++steps & 511u) == 0) {
        const double filled = double(network_.nodes.size()) * params_.sigma * params_.edgeLength;
        progress("network", std::min(0.99, filled / landArea));
      }
    }
  }

  /// A grid over the land and, per cell, the distance (m) from its centre to the nearest
  /// cell an edge of the network crosses.
  struct Coverage {
    geometry::Aabb box;
    double cell = kCoverageCell;
    int width = 0, height = 0;
    std::vector<float> distance;
    Vec2 centre(std::size_t i) const noexcept {
      return box.min + Vec2{(double(i % std::size_t(width)) + 0.5) * cell,
                            (double(i / std::size_t(width)) + 0.5) * cell};
    }
  };

  Coverage measureCoverage() const {
    Coverage c;
    c.box = land_.bounds();
    const Vec2 size = c.box.size();
    while ((size.x / c.cell + 1.0) * (size.y / c.cell + 1.0) > double(kMaxCoverageCells))
      c.cell *= 1.5;
    c.width = static_cast<int>(size.x / c.cell) + 1;
    c.height = static_cast<int>(size.y / c.cell) + 1;
    std::vector<std::uint8_t> onRiver(std::size_t(c.width) * std::size_t(c.height), 0);
    const auto mark = [&](Vec2 p) {
      const auto x = static_cast<int>(std::floor((p.x - c.box.min.x) / c.cell));
      const auto y = static_cast<int>(std::floor((p.y - c.box.min.y) / c.cell));
      if (x >= 0 && y >= 0 && x < c.width && y < c.height)
        onRiver[std::size_t(y) * std::size_t(c.width) + std::size_t(x)] = 1;
    };
    for (const RiverNode& n : network_.nodes) {
      mark(n.position);
      if (!n.parent.valid())
        continue;
      const Vec2 a = network_.nodes[n.parent.index()].position;
      const int steps = std::max(1, static_cast<int>(std::ceil(distance(a, n.position) / c.cell)));
      for (int k = 1; k < steps; ++k)
        mark(geometry::lerp(a, n.position, double(k) / steps));
    }
    c.distance = geometry::distanceToMarked(c.width, c.height, c.cell, onRiver);
    return c;
  }

  /// Starts growth toward every gap of the coverage (land farther than kCoverageGap from the
  /// network), farthest first: from the nearest nodes that can take another child without
  /// making a confluence of three, or from a new mouth on the nearest shore when that is
  /// nearer. Returns the number of seeds planted.
  std::size_t seedGaps() {
    const Coverage coverage = measureCoverage();
    std::vector<std::uint32_t> gaps;
    for (std::size_t i = 0; i < coverage.distance.size(); ++i)
      if (coverage.distance[i] > kCoverageGap && land_.contains(coverage.centre(i)))
        gaps.push_back(static_cast<std::uint32_t>(i));
    std::stable_sort(gaps.begin(), gaps.end(), [&](std::uint32_t a, std::uint32_t b) {
      return coverage.distance[a] > coverage.distance[b];
    });
    std::vector<Vec2> seeds;
    const auto expanded = static_cast<std::uint32_t>(network_.nodes.size());
    for (std::uint32_t g : gaps) {
      const Vec2 p = coverage.centre(g);
      const bool served = std::any_of(seeds.begin(), seeds.end(),
                                      [&](Vec2 s) { return distance(s, p) <= kCoverageGap; });
      if (served)
        continue;
      const double reach = coverage.distance[g] + params_.edgeLength;
      if (seedTowards(p, reach, expanded))
        seeds.push_back(p);
    }
    return seeds.size();
  }

  /// One seed toward gap point p: a child of a nearby node below `expanded` (the nodes that
  /// were expanded: a seed of this round will be, and would then take its children on top)
  /// or a new mouth, whichever lies nearer to p first.
  bool seedTowards(Vec2 p, double reach, std::uint32_t expanded) {
    std::vector<std::pair<double, NodeId>> near;
    geometry::Aabb box;
    box.add(p);
    nodeGrid_.query(box.expanded(reach), [&](std::uint32_t i) {
      const RiverNode& n = network_.nodes[i];
      const double d = distance(n.position, p);
      if (i < expanded && d <= reach && n.children.size() < 2 && n.parent.valid())
        near.emplace_back(d, NodeId(i));
      return true;
    });
    std::sort(near.begin(), near.end(), [](const auto& a, const auto& b) {
      return a.first < b.first || (a.first == b.first && a.second.value < b.second.value);
    });
    if (near.size() > std::size_t{kNodesPerGap})
      near.resize(kNodesPerGap);
    const double shore = land_.distanceToBoundary(p, reach);
    const bool shoreFirst = shore < reach && (near.empty() || shore < near[0].first);
    if (shoreFirst && mouthTowards(p, reach))
      return true;
    for (const auto& [d, id] : near) {
      const Vec2 to = p - network_.nodes[id.index()].position;
      const Vec2 dir = directions_[id.index()];
      const double angle = std::atan2(to.y, to.x) - std::atan2(dir.y, dir.x);
      if (tryChild(id, {angle, 1}))
        return true;
    }
    return !shoreFirst && shore < reach && mouthTowards(p, reach);
  }

  /// A new mouth at one of the shore sites nearest to p (within `reach`) whose first edge,
  /// straight inland, passes the rules of a grown child: clear of Γ, of other edges, and of κ.
  bool mouthTowards(Vec2 p, double reach) {
    if (!shoreSites_)
      shoreSites_ = shoreSites(params_, land_);
    std::vector<std::pair<double, std::size_t>> near;
    for (std::size_t i = 0; i < shoreSites_->size(); ++i)
      if (const double d = distance((*shoreSites_)[i].position, p); d <= reach)
        near.emplace_back(d, i);
    std::sort(near.begin(), near.end());
    if (near.size() > std::size_t{kShoreSitesPerGap})
      near.resize(kShoreSitesPerGap);
    for (const auto& [d, i] : near) {
      const MouthSite& site = (*shoreSites_)[i];
      const Vec2 child = site.position + site.inward * params_.edgeLength;
      const double z = std::max(params_.edgeLength * relief_.riverSlope(child), kMinRise);
      if (clearOfEdges(site.position, child, NodeId::invalid()) && slopesBelowKappa(child, z) &&
          barriers_.allows(site.position, child, {})) {
        addMouth(site, site.priority); // a candidate: growth gives it its children
        return true;
      }
    }
    return false;
  }

  void nodeAdded(NodeId id) override { pushCandidate(id); }

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
    if (places_[id.index()].river >= 0) {
      expandChainNode(id, n);
      return;
    }
    for (const ChildRequest& child : applyRules(n))
      tryChild(id, child);
  }

  /// A node of a drawn river's chain: its source grows headwaters like a node of priority 1
  /// (the drawn river begins there); every other chain node (it has its chain child already)
  /// takes one tributary, branching off at branchAngle on a random side (the other side if
  /// that fails) with a priority drawn as rule 2.2's side branch's.
  void expandChainNode(NodeId id, int n) {
    if (network_.nodes[id.index()].children.empty()) {
      for (const ChildRequest& child : applyRules(1))
        tryChild(id, child);
      return;
    }
    const double branch = params_.branchAngle * kDegree;
    const double side = rng_.chance(0.5) ? 1.0 : -1.0;
    const int m = n > 1 ? 1 + static_cast<int>(rng_.below(static_cast<std::uint32_t>(n - 1))) : 1;
    if (!tryChild(id, {side * branch, m}))
      tryChild(id, {-side * branch, m});
  }

  /// Adds the child if one of a few jittered directions passes valid(); whether it did.
  bool tryChild(NodeId parentId, const ChildRequest& child) {
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
        return true;
      }
    }
    return false;
  }

  base::Rng rng_;
  std::vector<MinHeap> heaps_; // candidates X by priority
  std::size_t candidateCount_ = 0;
  std::size_t highPriorityCount_ = 0;                // candidates with priority > 1
  std::optional<std::vector<MouthSite>> shoreSites_; // for gap mouths, sampled when first needed
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
  if (spec.params.grower == input::NetworkGrower::kDla)
    return growNetworkDla(spec, land, mouths, progress);
  return growNetwork(spec, land, mouths, progress);
}

} // namespace strahler::network
