#include "strahler/network/dla_growth.h"

#include "growing_network.h"

#include "strahler/base/random.h"
#include "strahler/geometry/distance.h"
#include "strahler/geometry/grid_index.h"
#include "strahler/network/drawn_rivers.h"
#include "strahler/network/relief_law.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

namespace strahler::network {
namespace {

using detail::kMinRise;
using geometry::Vec2;

constexpr std::uint64_t kDlaStream = 0x646c61ull;
constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kMaxNodes = 2'000'000.0;  // memory bound on one network (as the grammar's)
constexpr double kParticlesPerNode = 40.0; // particle budget per expected node
constexpr int kMaxWalkSteps = 4000;        // steps of one walk before it is dropped
constexpr int kLaunchTries = 64;           // random points tried to launch one particle
constexpr int kMaxStickTries = 24;         // refused sticking draws before a walk is dropped
constexpr int kSaturationFailures = 4000;  // consecutive failed particles: saturated
constexpr double kSearchEdges = 6.0;       // far nearest-node search radius, in e
constexpr double kMinStepEdges = 0.3;      // shortest step, in e
constexpr double kStickFloor = 0.15;       // sticking probability against the preference
constexpr double kStickSharpness = 2.0;    // exponent of the directional preference
constexpr double kSteer = 1.5;             // weight of the mountainousness gradient
constexpr int kCandidatesPerStick = 3;     // nodes within reach tried for one particle

/// The nearest node to a point and its distance (infinite when none within the search).
struct Nearest {
  double distance = std::numeric_limits<double>::infinity();
  std::uint32_t node = 0;
};

class DlaGrower : private detail::GrowingNetwork {
public:
  DlaGrower(const input::WorldSpec& spec, const geometry::PolygonIndex& land)
      : GrowingNetwork(spec, land), rng_(spec.params.seed, kDlaStream), box_(land.bounds()) {}

  RiverNetwork run(const std::vector<MouthSite>& mouths, const base::ProgressCallback& progress,
                   double landArea) {
    for (const MouthSite& m : mouths)
      addMouth(m, 1);
    for (std::size_t i = 0; i < mouths.size(); ++i)
      if (mouths[i].drawnRiver >= 0)
        addChain(network_.mouths[i].node, mouths[i].drawnRiver, 1);
    const double expected = landArea / (params_.sigma * params_.edgeLength);
    const auto budget = static_cast<std::size_t>(kParticlesPerNode * expected) + 1000;
    int failures = network_.nodes.empty() ? kSaturationFailures : 0; // nothing to stick to
    for (std::size_t particle = 0; particle < budget && failures < kSaturationFailures;
         ++particle) {
      failures = releaseParticle() ? 0 : failures + 1;
      if (progress && (particle & 4095u) == 0)
        progress("network", std::min(0.99, double(network_.nodes.size()) / expected));
    }
    pruneTwigs();
    computeStrahlerNumbers(network_);
    for (RiverNode& n : network_.nodes)
      n.priority = n.strahler;
    if (progress)
      progress("network", 1.0);
    return std::move(network_);
  }

private:
  double e() const noexcept { return params_.edgeLength; }

  /// The nearest node to p within `radius` (grid cells of side e around p).
  Nearest nearestNode(Vec2 p, double radius) const {
    Nearest best;
    geometry::Aabb box;
    box.add(p);
    nodeGrid_.query(box.expanded(radius), [&](std::uint32_t i) {
      const double d = distance(network_.nodes[i].position, p);
      if (d < best.distance || (d == best.distance && i < best.node))
        best = {d, i};
      return true;
    });
    if (best.distance > radius)
      best.distance = std::numeric_limits<double>::infinity();
    return best;
  }

  /// Distance from p to the network: near first, then farther; capped at kSearchEdges · e.
  double distanceToNetwork(Vec2 p) const {
    const Nearest near = nearestNode(p, 1.5 * e());
    if (std::isfinite(near.distance))
      return near.distance;
    return std::min(nearestNode(p, kSearchEdges * e()).distance, kSearchEdges * e());
  }

  /// A random land point farther than e from every node (Masek: an unoccupied site).
  std::optional<Vec2> launchPoint() {
    const Vec2 size = box_.size();
    for (int t = 0; t < kLaunchTries; ++t) {
      const Vec2 p = box_.min + Vec2{rng_.uniform() * size.x, rng_.uniform() * size.y};
      if (land_.contains(p) && distanceToNetwork(p) > e())
        return p;
    }
    return std::nullopt;
  }

  /// One particle: launched, walked, stuck or dropped. Whether it added a node.
  bool releaseParticle() {
    std::optional<Vec2> start = launchPoint();
    if (!start)
      return false;
    Vec2 p = *start;
    int stickTries = 0;
    for (int step = 0; step < kMaxWalkSteps; ++step) {
      const double d = distanceToNetwork(p);
      if (d <= e()) {
        const StickOutcome outcome = tryStick(p);
        if (outcome == StickOutcome::kStuck)
          return true;
        if (outcome == StickOutcome::kDropped || ++stickTries > kMaxStickTries)
          return false;
      }
      const double length = std::max(kMinStepEdges * e(), d - e());
      const double angle = rng_.uniform(0.0, 2.0 * std::numbers::pi);
      const Vec2 q = p + geometry::direction(angle) * length;
      if (land_.contains(q))
        p = q; // a step out of Ω is refused: the walker stays in land
    }
    return false;
  }

  enum class StickOutcome { kStuck, kRefused, kDropped };

  /// The particle at p is within e of the network: it sticks (a new node), is refused by the
  /// sticking probability (it walks on), or is dropped (no valid edge toward it).
  StickOutcome tryStick(Vec2 p) {
    std::vector<std::pair<double, std::uint32_t>> near;
    geometry::Aabb box;
    box.add(p);
    nodeGrid_.query(box.expanded(e()), [&](std::uint32_t i) {
      const RiverNode& n = network_.nodes[i];
      const double d = distance(n.position, p);
      if (d <= e() && n.children.size() < 2)
        near.emplace_back(d, i);
      return true;
    });
    if (near.empty())
      return StickOutcome::kDropped;
    std::sort(near.begin(), near.end());
    const RiverNode& first = network_.nodes[near[0].second];
    const Vec2 toward =
        near[0].first > 0.0 ? normalize(p - first.position) : directions_[near[0].second];
    if (!rng_.chance(stickProbability(near[0].second, toward)))
      return StickOutcome::kRefused;
    const std::size_t tries = std::min<std::size_t>(near.size(), kCandidatesPerStick);
    for (std::size_t k = 0; k < tries; ++k) {
      const NodeId parentId(near[k].second);
      const RiverNode& parent = network_.nodes[parentId.index()];
      if (near[k].first <= 0.0)
        continue;
      const std::optional<Vec2> dir = childDirection(parentId, normalize(p - parent.position));
      if (!dir)
        continue;
      const Vec2 child = parent.position + *dir * e();
      const double rise =
          e() * relief_.riverSlope(child) * (1.0 + params_.slopeJitter * rng_.uniform(-1.0, 1.0));
      const double z = parent.elevation + std::max(rise, kMinRise);
      if (valid(parentId, child, z)) {
        addNode(child, z, parentId, 1, *dir);
        return StickOutcome::kStuck;
      }
    }
    return StickOutcome::kDropped;
  }

  /// The direction of a new edge from `parentId` toward a particle coming from `toward`,
  /// turned back into the grammar's cone (at most branchAngle + angleJitter from the parent's
  /// flow direction: no hairpins the river primitives could not follow); none when it would
  /// run closer than 0.6 branchAngle to the parent's other child (no near-overlapping siblings).
  std::optional<Vec2> childDirection(NodeId parentId, Vec2 toward) const {
    const Vec2 flow = directions_[parentId.index()];
    const double maxTurn = (params_.branchAngle + params_.angleJitter) * kDegree;
    double turn = std::atan2(cross(flow, toward), dot(flow, toward));
    turn = std::clamp(turn, -maxTurn, maxTurn);
    const double flowAngle = std::atan2(flow.y, flow.x);
    const Vec2 dir = geometry::direction(flowAngle + turn);
    for (NodeId sibling : network_.nodes[parentId.index()].children) {
      const Vec2 other = directions_[sibling.index()];
      if (std::atan2(std::abs(cross(other, dir)), dot(other, dir)) <
          0.6 * params_.branchAngle * kDegree)
        return std::nullopt;
    }
    return dir;
  }

  /// Seed 001's anisotropic sticking: a floor plus a share that grows with the cosine between
  /// the new edge `toward` and the node's preferred direction.
  double stickProbability(std::uint32_t node, Vec2 toward) const {
    const Vec2 preferred = preferredDirection(node);
    const double c = (1.0 + dot(toward, preferred)) * 0.5;
    return kStickFloor + (1.0 - kStickFloor) * std::pow(c, kStickSharpness);
  }

  /// The node's flow direction (upstream), bent up the gradient of the mountainousness.
  Vec2 preferredDirection(std::uint32_t node) const {
    const Vec2 at = network_.nodes[node].position;
    const Vec2 dir = directions_[node];
    const double h = e();
    const Vec2 gradient{
        relief_.mountainousness(at + Vec2{h, 0.0}) - relief_.mountainousness(at - Vec2{h, 0.0}),
        relief_.mountainousness(at + Vec2{0.0, h}) - relief_.mountainousness(at - Vec2{0.0, h})};
    const double g = length(gradient);
    if (!(g > 1e-9))
      return dir;
    // m changes by at most 2 over 2h; a change of 1 over a coast ramp counts fully.
    const double weight = kSteer * std::min(1.0, g / (2.0 * h) * params_.coastRamp);
    const Vec2 bent = dir + gradient / g * weight;
    return length(bent) > 1e-9 ? normalize(bent) : dir;
  }

  /// Whether a node other than leaf `i`, its parent and its siblings lies within 1.5 e of it:
  /// then cutting the leaf leaves no gap in the coverage.
  bool hasNeighbourBesides(std::size_t i) const {
    const RiverNode& leaf = network_.nodes[i];
    geometry::Aabb box;
    box.add(leaf.position);
    const double reach = 1.5 * e();
    return !nodeGrid_.query(box.expanded(reach), [&](std::uint32_t j) {
      const RiverNode& other = network_.nodes[j];
      const bool family = j == i || j == leaf.parent.value || other.parent == leaf.parent;
      return family || distance(other.position, leaf.position) > reach;
    });
  }

  /// Seed 001's pruning of a saturated aggregate, at its lightest: a leaf hanging off a node of
  /// Strahler order ≥ 2 (a first-order stream of one edge beside a larger river) is cut when
  /// other rivers pass near its tip, so the rivers keep long, slender tributaries instead of a
  /// fringe of stubs, and the coverage stays. Drawn-river chains and mouths are kept; nodes are
  /// renumbered in order, so parents still come first.
  void pruneTwigs() {
    computeStrahlerNumbers(network_);
    std::vector<NodeId> remap(network_.nodes.size());
    std::vector<bool> keep(network_.nodes.size(), true);
    for (std::size_t i = 0; i < network_.nodes.size(); ++i) {
      const RiverNode& n = network_.nodes[i];
      if (!n.children.empty() || !n.parent.valid() || places_[i].river >= 0)
        continue;
      const RiverNode& up = network_.nodes[n.parent.index()];
      if (up.strahler >= 2 && up.parent.valid() && hasNeighbourBesides(i))
        keep[i] = false;
    }
    RiverNetwork pruned;
    pruned.edgeLength = network_.edgeLength;
    for (std::size_t i = 0; i < network_.nodes.size(); ++i) {
      if (!keep[i])
        continue;
      RiverNode n = network_.nodes[i];
      remap[i] = NodeId(static_cast<std::uint32_t>(pruned.nodes.size()));
      n.children.clear();
      if (n.parent.valid()) {
        n.parent = remap[n.parent.index()];
        pruned.nodes[n.parent.index()].children.push_back(remap[i]);
      }
      pruned.nodes.push_back(std::move(n));
    }
    for (Mouth m : network_.mouths) {
      m.node = remap[m.node.index()];
      pruned.mouths.push_back(m);
    }
    network_ = std::move(pruned);
  }

  base::Rng rng_;
  geometry::Aabb box_; // where particles are launched (rejection on Ω)
};

} // namespace

base::Result<RiverNetwork> growNetworkDla(const input::WorldSpec& spec,
                                          const geometry::PolygonIndex& land,
                                          const std::vector<MouthSite>& mouths,
                                          const base::ProgressCallback& progress) {
  const double landArea = geometry::area(land.polygons());
  const double expectedNodes = landArea / (spec.params.sigma * spec.params.edgeLength);
  if (expectedNodes > kMaxNodes)
    return base::makeError(
        base::ErrorCode::kLimitExceeded,
        "this world would have about " + std::to_string(static_cast<long long>(expectedNodes)) +
            " river nodes, more than the limit of 2000000: raise edgeLength or sigma");
  DlaGrower grower(spec, land);
  return grower.run(mouths, progress, std::max(landArea, 1.0));
}

} // namespace strahler::network
