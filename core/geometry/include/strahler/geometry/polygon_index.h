#pragma once

#include "strahler/geometry/grid_index.h"
#include "strahler/geometry/polygon.h"

#include <cstdint>
#include <span>
#include <vector>

namespace strahler::geometry {

/// One edge of a polygon boundary, with the ring it belongs to.
struct BoundarySegment {
  Vec2 a;
  Vec2 b;
  std::uint32_t ring = 0; ///< Index into PolygonIndex::rings().
};

/// Result of a nearest-boundary query.
struct BoundaryHit {
  double distance = 0.0;     ///< Distance to the boundary (the search limit if nothing closer).
  Vec2 point{};              ///< Closest boundary point (undefined when nothing was found).
  std::int64_t segment = -1; ///< Index of the closest segment, -1 when none within the limit.
};

/// Accelerated queries on a fixed multipolygon (land with lakes): point inside, distance to
/// the boundary (coast and lake shores), segment clearance. Each query costs O(segments
/// nearby), not O(all segments).
class PolygonIndex {
public:
  /// Indexes `polygons`; cell size defaults to a few times the mean segment length.
  explicit PolygonIndex(MultiPolygon polygons, double cellSize = 0.0);

  /// The indexed polygons.
  const MultiPolygon& polygons() const noexcept { return polygons_; }
  /// All rings (outer and holes) in a flat list, in polygon order.
  const std::vector<const Ring*>& rings() const noexcept { return rings_; }
  /// True when ring `i` of rings() is a hole (a lake shore).
  bool isHole(std::size_t i) const noexcept { return ringIsHole_[i]; }
  /// Every boundary segment.
  const std::vector<BoundarySegment>& segments() const noexcept { return segments_; }
  /// Bounding box of the polygons.
  const Aabb& bounds() const noexcept { return bounds_; }

  /// True when p is inside the multipolygon (inside an outer ring, outside its holes).
  bool contains(Vec2 p) const noexcept;
  /// The segments contains() tests for points at height y (y within the bounds, required): those
  /// whose y-range meets y's horizontal band, with the band's index. A point inside the bounds is
  /// inside the multipolygon when an odd number of them cross the ray from it towards +x:
  /// (a.y > y) != (b.y > y) and x < a.x + (y − a.y) / (b.y − a.y) · (b.x − a.x).
  struct RayBand {
    std::size_t index = 0;
    std::span<const std::uint32_t> segments;
  };
  RayBand rayBand(double y) const noexcept;
  /// Nearest boundary point to p, searching no farther than maxDistance.
  BoundaryHit nearestBoundary(Vec2 p, double maxDistance) const noexcept;
  /// Distance from p to the boundary, capped at maxDistance.
  double distanceToBoundary(Vec2 p, double maxDistance) const noexcept {
    return nearestBoundary(p, maxDistance).distance;
  }
  /// What the index knows cheaply about the boundary near a box: no point of it lies nearer to
  /// the boundary than `distance` (0: unknown), and all of them lie inside (`inside`) or all
  /// outside, when `distance` is positive. From bounds kept per cell of the index's grid;
  /// nothing is known outside the grid.
  struct Clearance {
    double distance = 0.0;
    bool inside = false;
  };
  Clearance clearance(const Aabb& box) const noexcept;
  /// Appends to `out` the index of every segment whose bounding box meets `box`, each once,
  /// ascending.
  void segmentsMeeting(const Aabb& box, std::vector<std::uint32_t>& out) const;
  /// True when some boundary segment comes closer than `clearance` to segment [a, b]
  /// (clearance 0: when [a, b] touches or crosses the boundary).
  bool segmentNearBoundary(Vec2 a, Vec2 b, double clearance) const noexcept;

private:
  MultiPolygon polygons_;
  std::vector<const Ring*> rings_;
  std::vector<bool> ringIsHole_;
  /// The centre of cell (x, y) of the flattened grid (the cells of grid_).
  Vec2 cellCenter(int x, int y) const noexcept;
  /// The index of cell (x, y) in the per-cell arrays.
  std::size_t cellIndex(int x, int y) const noexcept {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(nx_) +
           static_cast<std::size_t>(x);
  }

  std::vector<BoundarySegment> segments_;
  Aabb bounds_;
  GridIndex grid_;
  // Horizontal bands for ray casting: the segments whose y-range meets band b are
  // bandSegments_[bandBegin_[b] .. bandBegin_[b + 1]).
  double bandHeight_ = 1.0;
  std::vector<std::uint32_t> bandBegin_;
  std::vector<std::uint32_t> bandSegments_;
  // The grid's cells flattened (offsets into cellSegments_), for the nearest-boundary search,
  // which walks cells itself so it can skip those farther than the best hit so far.
  int nx_ = 1;
  int ny_ = 1;
  std::vector<std::uint32_t> cellBegin_;
  std::vector<std::uint32_t> cellSegments_;
  // Per cell: the segment nearest to its centre within a few cells (-1: none), the first
  // bound of a nearest-boundary search from a point of that cell.
  std::vector<std::int32_t> cellSeed_;
  // Per cell: how near to the boundary a point of it may come at least (0: unknown), and
  // whether its centre (then every point, where that is positive) lies inside.
  std::vector<double> cellClearance_;
  std::vector<bool> cellInside_;
};

} // namespace strahler::geometry
