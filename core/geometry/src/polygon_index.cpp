#include "strahler/geometry/polygon_index.h"

#include "strahler/geometry/distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace strahler::geometry {

PolygonIndex::PolygonIndex(MultiPolygon polygons, double cellSize)
    : polygons_(std::move(polygons)) {
  for (const Polygon& p : polygons_) {
    rings_.push_back(&p.outer);
    ringIsHole_.push_back(false);
    for (const Ring& h : p.holes) {
      rings_.push_back(&h);
      ringIsHole_.push_back(true);
    }
  }
  double totalLength = 0.0;
  for (std::uint32_t r = 0; r < rings_.size(); ++r) {
    const Ring& ring = *rings_[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      segments_.push_back({a, b, r});
      totalLength += distance(a, b);
      bounds_.add(a);
    }
  }
  if (bounds_.empty())
    bounds_.add(Vec2{0, 0});
  const double meanLength = segments_.empty() ? 1.0 : totalLength / double(segments_.size());
  if (cellSize <= 0.0) {
    const Vec2 size = bounds_.size();
    const double byArea = std::sqrt(std::max(size.x * size.y, 1.0) /
                                    double(std::max<std::size_t>(segments_.size(), 1)));
    cellSize = std::max({4.0 * meanLength, byArea, 1.0});
  }
  grid_ = GridIndex(bounds_, cellSize);
  for (std::uint32_t i = 0; i < segments_.size(); ++i) {
    Aabb box;
    box.add(segments_[i].a);
    box.add(segments_[i].b);
    grid_.insert(box, i);
  }
  {
    // Same cell layout as grid_ (origin bounds_.min, side cellSize()): read each cell
    // through its centre.
    const double side = grid_.cellSize();
    nx_ = static_cast<int>(std::floor(bounds_.size().x / side)) + 1;
    ny_ = static_cast<int>(std::floor(bounds_.size().y / side)) + 1;
    cellBegin_.reserve(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) + 1);
    cellBegin_.push_back(0);
    for (int y = 0; y < ny_; ++y)
      for (int x = 0; x < nx_; ++x) {
        const std::vector<std::uint32_t>& ids = grid_.cellAt(cellCenter(x, y));
        cellSegments_.insert(cellSegments_.end(), ids.begin(), ids.end());
        cellBegin_.push_back(static_cast<std::uint32_t>(cellSegments_.size()));
      }
  }
  {
    // Bounded (a few cells) so that building stays linear in the number of cells.
    const double side = grid_.cellSize();
    cellSeed_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), -1);
    cellClearance_.assign(cellSeed_.size(), 0.0);
    const double halfDiagonal = side * std::sqrt(0.5);
    for (int y = 0; y < ny_; ++y)
      for (int x = 0; x < nx_; ++x) {
        const std::size_t cell = cellIndex(x, y);
        const BoundaryHit hit = nearestBoundary(cellCenter(x, y), 3.0 * side);
        cellSeed_[cell] = static_cast<std::int32_t>(hit.segment);
        // The distance found (or the search's limit) less the cell's half diagonal, with a
        // margin far above rounding: no point of the cell is nearer the boundary.
        cellClearance_[cell] = std::max(0.0, (hit.distance - halfDiagonal) * (1.0 - 1e-9) - 1e-6);
      }
  }
  // Bands about a segment tall: a band then lists little more than the segments that cross
  // its lines (a segment is listed in 1 + its height / bandHeight_ bands), and at most about
  // four bands per segment.
  bandHeight_ =
      std::max({meanLength, bounds_.size().y / (4.0 * double(segments_.size()) + 1.0), 1e-9});
  const auto bandCount = static_cast<std::size_t>(std::floor(bounds_.size().y / bandHeight_)) + 1;
  const auto bandsOf = [&](const BoundarySegment& s) {
    const double y0 = std::min(s.a.y, s.b.y) - bounds_.min.y;
    const double y1 = std::max(s.a.y, s.b.y) - bounds_.min.y;
    return std::pair{
        static_cast<std::size_t>(std::max(0.0, std::floor(y0 / bandHeight_))),
        std::min(bandCount - 1, static_cast<std::size_t>(std::floor(y1 / bandHeight_)))};
  };
  bandBegin_.assign(bandCount + 1, 0);
  for (const BoundarySegment& s : segments_) {
    const auto [b0, b1] = bandsOf(s);
    for (std::size_t b = b0; b <= b1; ++b)
      ++bandBegin_[b + 1];
  }
  for (std::size_t b = 0; b < bandCount; ++b)
    bandBegin_[b + 1] += bandBegin_[b];
  bandSegments_.resize(bandBegin_.back());
  std::vector<std::uint32_t> next(bandBegin_.begin(), bandBegin_.end() - 1);
  for (std::uint32_t i = 0; i < segments_.size(); ++i) {
    const auto [b0, b1] = bandsOf(segments_[i]);
    for (std::size_t b = b0; b <= b1; ++b)
      bandSegments_[next[b]++] = i;
  }
  // A cell clear of the boundary lies wholly on the side of its centre.
  cellInside_.assign(cellSeed_.size(), false);
  for (int y = 0; y < ny_; ++y)
    for (int x = 0; x < nx_; ++x)
      cellInside_[cellIndex(x, y)] = contains(cellCenter(x, y));
}

Vec2 PolygonIndex::cellCenter(int x, int y) const noexcept {
  const double side = grid_.cellSize();
  return {bounds_.min.x + (x + 0.5) * side, bounds_.min.y + (y + 0.5) * side};
}

PolygonIndex::Clearance PolygonIndex::clearance(const Aabb& box) const noexcept {
  const double side = grid_.cellSize();
  const double x0 = std::floor((box.min.x - bounds_.min.x) / side);
  const double x1 = std::floor((box.max.x - bounds_.min.x) / side);
  const double y0 = std::floor((box.min.y - bounds_.min.y) / side);
  const double y1 = std::floor((box.max.y - bounds_.min.y) / side);
  if (!(x0 >= 0.0 && y0 >= 0.0 && x1 < nx_ && y1 < ny_ && x0 <= x1 && y0 <= y1))
    return {};
  const auto xFirst = static_cast<int>(x0), xLast = static_cast<int>(x1);
  const auto yFirst = static_cast<int>(y0), yLast = static_cast<int>(y1);
  Clearance clear{std::numeric_limits<double>::infinity(), cellInside_[cellIndex(xFirst, yFirst)]};
  for (int y = yFirst; y <= yLast; ++y)
    for (int x = xFirst; x <= xLast; ++x) {
      const std::size_t cell = cellIndex(x, y);
      if (cellInside_[cell] != clear.inside)
        return {};
      clear.distance = std::min(clear.distance, cellClearance_[cell]);
    }
  return clear;
}

PolygonIndex::RayBand PolygonIndex::rayBand(double y) const noexcept {
  const auto band =
      std::min(bandBegin_.size() - 2, static_cast<std::size_t>((y - bounds_.min.y) / bandHeight_));
  return {
      band,
      std::span(bandSegments_).subspan(bandBegin_[band], bandBegin_[band + 1] - bandBegin_[band])};
}

bool PolygonIndex::contains(Vec2 p) const noexcept {
  if (!bounds_.contains(p))
    return false;
  bool inside = false;
  for (const std::uint32_t i : rayBand(p.y).segments) {
    const Vec2 a = segments_[i].a, b = segments_[i].b;
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
      if (p.x < x)
        inside = !inside;
    }
  }
  return inside;
}

BoundaryHit PolygonIndex::nearestBoundary(Vec2 p, double maxDistance) const noexcept {
  BoundaryHit hit{maxDistance, p, -1};
  double best2 = maxDistance * maxDistance;
  const double cell = grid_.cellSize();
  const int cx = std::clamp(static_cast<int>(std::floor((p.x - bounds_.min.x) / cell)), 0, nx_ - 1);
  const int cy = std::clamp(static_cast<int>(std::floor((p.y - bounds_.min.y) / cell)), 0, ny_ - 1);
  // Squared distance from p to the box [lo, hi] (0 inside).
  auto boxDistance2 = [&](double loX, double loY, double hiX, double hiY) {
    const double dx = std::max({loX - p.x, 0.0, p.x - hiX});
    const double dy = std::max({loY - p.y, 0.0, p.y - hiY});
    return dx * dx + dy * dy;
  };
  // Start from the segment nearest to the centre of p's cell: a real candidate, so the
  // minimum is unchanged, but the bound is tight from the first ring on.
  if (!cellSeed_.empty()) {
    const std::int32_t seed = cellSeed_[cellIndex(cx, cy)];
    if (seed >= 0) {
      const auto i = static_cast<std::uint32_t>(seed);
      const Vec2 q = closestPointOnSegment(p, segments_[i].a, segments_[i].b);
      const double d2 = lengthSquared(q - p);
      if (d2 < best2) {
        best2 = d2;
        hit.point = q;
        hit.segment = i;
      }
    }
  }
  auto visitCell = [&](int x, int y) {
    const std::size_t c = cellIndex(x, y);
    if (cellBegin_[c] == cellBegin_[c + 1])
      return;
    // The closest point of a segment lies in some cell that lists it, so skipping cells no
    // closer than the best hit cannot lose the minimum (ties keep the same distance).
    const double lx = bounds_.min.x + x * cell, ly = bounds_.min.y + y * cell;
    if (boxDistance2(lx, ly, lx + cell, ly + cell) >= best2)
      return;
    for (std::uint32_t k = cellBegin_[c]; k < cellBegin_[c + 1]; ++k) {
      const std::uint32_t i = cellSegments_[k];
      const Vec2 a = segments_[i].a, b = segments_[i].b;
      // A segment is no closer than its bounding box: most are rejected without the
      // projection.
      if (boxDistance2(std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x),
                       std::max(a.y, b.y)) >= best2)
        continue;
      const Vec2 q = closestPointOnSegment(p, a, b);
      const double d2 = lengthSquared(q - p);
      if (d2 < best2) {
        best2 = d2;
        hit.point = q;
        hit.segment = i;
      }
    }
  };
  // Expanding rings of cells around p's cell (clamped to the grid); cells of ring r are at
  // least (r - 1) cells away from p.
  for (int r = 0;; ++r) {
    const double ringMin = (r - 1) * cell;
    if (r > 0 && ringMin > 0 && ringMin * ringMin > best2)
      break;
    bool any = false;
    for (int y = cy - r; y <= cy + r; ++y) {
      if (y < 0 || y >= ny_)
        continue;
      const bool edgeRow = (y == cy - r || y == cy + r);
      for (int x = cx - r; x <= cx + r; x += (edgeRow || r == 0) ? 1 : 2 * r) {
        if (x < 0 || x >= nx_)
          continue;
        any = true;
        visitCell(x, y);
      }
    }
    if (!any)
      break; // every further ring lies outside the grid too
  }
  if (hit.segment >= 0)
    hit.distance = std::sqrt(best2);
  return hit;
}

void PolygonIndex::segmentsMeeting(const Aabb& box, std::vector<std::uint32_t>& out) const {
  const std::size_t first = out.size();
  grid_.query(box, [&](std::uint32_t i) {
    Aabb b;
    b.add(segments_[i].a);
    b.add(segments_[i].b);
    if (b.intersects(box))
      out.push_back(i);
    return true;
  });
  // A segment spanning several cells is reported by each.
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
  out.erase(std::unique(out.begin() + static_cast<std::ptrdiff_t>(first), out.end()), out.end());
}

bool PolygonIndex::segmentNearBoundary(Vec2 a, Vec2 b, double clearance) const noexcept {
  Aabb box;
  box.add(a);
  box.add(b);
  box = box.expanded(clearance);
  bool near = false;
  grid_.query(box, [&](std::uint32_t i) {
    const double d = segmentSegmentDistance(a, b, segments_[i].a, segments_[i].b);
    if (d < clearance || (clearance == 0.0 && d == 0.0))
      near = true;
    return !near;
  });
  return near;
}

} // namespace strahler::geometry
