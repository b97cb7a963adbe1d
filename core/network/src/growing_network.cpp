#include "growing_network.h"

#include "edge_rules.h"

#include "strahler/geometry/distance.h"

#include <algorithm>
#include <cmath>

namespace strahler::network::detail {
namespace {

using geometry::Vec2;

constexpr double kSlopeRadiusEdges = 3.0; // κ test radius, in edge lengths

/// The courses of the drawn rivers (spec.features.rivers), by index.
std::vector<std::optional<DrawnCourse>> drawnCourses(const input::WorldSpec& spec,
                                                     const geometry::PolygonIndex& land) {
  std::vector<std::optional<DrawnCourse>> courses;
  for (const input::RiverFeature& r : spec.features.rivers)
    courses.push_back(drawnCourse(r, land, spec.params));
  return courses;
}

} // namespace

GrowingNetwork::GrowingNetwork(const input::WorldSpec& spec, const geometry::PolygonIndex& land)
    : params_(spec.params), land_(land), relief_(spec, land),
      edges_(land.bounds().expanded(spec.params.edgeLength), spec.params.sigma),
      nodeGrid_(land.bounds().expanded(spec.params.edgeLength), spec.params.edgeLength),
      courses_(drawnCourses(spec, land)), barriers_(spec, land, courses_) {
  network_.edgeLength = params_.edgeLength;
}

NodeId GrowingNetwork::addNode(Vec2 p, double z, NodeId parent, int priority, Vec2 dir) {
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
  places_.push_back({});
  nodeAdded(id);
  return id;
}

void GrowingNetwork::addMouth(const MouthSite& m, int priority) {
  const NodeId id = addNode(m.position, 0.0, NodeId::invalid(), priority, m.inward);
  network_.mouths.push_back({id, m.inward, m.onLake});
  network_.nodes[id.index()].tree = static_cast<std::uint32_t>(network_.mouths.size() - 1);
}

void GrowingNetwork::addChain(NodeId mouth, int river, int priority) {
  const auto& course = courses_[static_cast<std::size_t>(river)];
  if (!course)
    return;
  const std::size_t last = course->chain.size() - 1;
  const auto placeOf = [&](std::size_t k) {
    return ChainPlace{river, course->chain[std::min(k + 1, last)],
                      course->chain[k == 0 ? 0 : k - 1]};
  };
  places_[mouth.index()] = placeOf(0);
  NodeId parent = mouth;
  for (std::size_t k = 1; k <= last; ++k) {
    const Vec2 from = network_.nodes[parent.index()].position;
    const Vec2 p = course->node(k);
    const double rise = distance(from, p) * relief_.riverSlope(geometry::lerp(from, p, 0.5));
    const double z = network_.nodes[parent.index()].elevation + std::max(rise, kMinRise);
    const Vec2 dir = distance(from, p) > 0.0 ? normalize(p - from) : directions_[parent.index()];
    parent = addNode(p, z, parent, priority, dir);
    places_[parent.index()] = placeOf(k);
  }
}

bool GrowingNetwork::valid(NodeId parentId, Vec2 p, double z) const {
  const RiverNode& parent = network_.nodes[parentId.index()];
  const bool fromMouth = !parent.parent.valid();
  if (fromMouth ? !mouthEdgeValid(land_, parent.position, p, params_.delta)
                : !innerEdgeValid(land_, parent.position, p, params_.delta))
    return false;
  return clearOfEdges(parent.position, p, parentId) && slopesBelowKappa(p, z) &&
         barriers_.allows(parent.position, p, places_[parentId.index()]);
}

bool GrowingNetwork::clearOfEdges(Vec2 from, Vec2 p, NodeId fromId) const {
  geometry::Aabb box;
  box.add(from);
  box.add(p);
  return edges_.query(box.expanded(params_.sigma), [&](std::uint32_t c) {
    const RiverNode& other = network_.nodes[c];
    // Edges sharing the parent node are adjacent: the parent's own edge and its siblings'.
    if (fromId.valid() && (c == fromId.value || other.parent == fromId))
      return true;
    const Vec2 a = network_.nodes[other.parent.index()].position;
    return geometry::segmentSegmentDistance(from, p, a, other.position) > params_.sigma;
  });
}

bool GrowingNetwork::slopesBelowKappa(Vec2 p, double z) const {
  const double radius = kSlopeRadiusEdges * params_.edgeLength;
  geometry::Aabb box;
  box.add(p);
  return nodeGrid_.query(box.expanded(radius), [&](std::uint32_t i) {
    const RiverNode& other = network_.nodes[i];
    const double d = distance(other.position, p);
    return d > radius || std::abs(z - other.elevation) < params_.kappa * d;
  });
}

} // namespace strahler::network::detail
