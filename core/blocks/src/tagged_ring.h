#pragma once

#include "strahler/base/strong_id.h"
#include "strahler/blocks/block_set.h"
#include "strahler/geometry/aabb.h"
#include "strahler/geometry/polygon.h"

#include <cstdint>
#include <vector>

namespace strahler::blocks::detail {

/// A convex polygon whose corners and edges carry the tags of Block: corner i is Voronoi
/// vertex vertices[i] (or kNoVertex), edge points[i]→points[i+1] separates the cell from node
/// neighbours[i] (or invalid). The three vectors always have the same length.
struct TaggedRing {
  geometry::Ring points;
  std::vector<std::uint32_t> vertices;
  std::vector<NodeId> neighbours;

  /// Appends a corner and the tag of the edge that leaves it.
  void push(geometry::Vec2 p, std::uint32_t vertex, NodeId neighbour) {
    points.push_back(p);
    vertices.push_back(vertex);
    neighbours.push_back(neighbour);
  }
  /// Number of corners.
  std::size_t size() const noexcept { return points.size(); }
};

/// The box as a counter-clockwise ring with untagged corners and edges.
TaggedRing boxRing(const geometry::Aabb& box);

/// Keeps the part of `ring` where dot(p - origin, normal) <= 0; the edge the cut creates is
/// tagged `neighbour`, the corners it creates kNoVertex. Points exactly on the line stay.
void clipHalfPlane(TaggedRing& ring, geometry::Vec2 origin, geometry::Vec2 normal,
                   NodeId neighbour);

/// Relative distance under which two Voronoi vertices count as one corner.
inline constexpr double kCoincidentCorner = 1e-9;

/// Merges consecutive corners that are one point: exactly equal, or two Voronoi vertices
/// closer than kCoincidentCorner times their radius (cocircular sites give several
/// circumcentres that differ by rounding only). The edge between them goes; the surviving
/// corner keeps its own vertex tag and the other edges keep theirs. The decision depends on
/// the two corners only, so the cells on both sides of an edge agree.
void dropCoincidentCorners(TaggedRing& ring, const std::vector<VoronoiVertex>& vertices);

} // namespace strahler::blocks::detail
