#include "strahler/tiling/water_mask.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::tiling {
namespace {

using geometry::Aabb;
using geometry::Vec2;

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

/// Distance² from p to the segment [a, b].
double distance2ToSegment(Vec2 p, Vec2 a, Vec2 b) noexcept {
  const Vec2 ab = b - a;
  const double l2 = ab.x * ab.x + ab.y * ab.y;
  const double t =
      l2 > 0.0 ? std::clamp(((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / l2, 0.0, 1.0) : 0.0;
  const Vec2 d = p - (a + ab * t);
  return d.x * d.x + d.y * d.y;
}

/// The box of the points.
Aabb boundsOf(const std::vector<Vec2>& points) {
  Aabb box;
  for (Vec2 p : points)
    box.add(p);
  return box;
}

} // namespace

WaterMask::WaterMask(const construction::World& world, const geometry::LocalProjection& projection)
    : world_(world), projection_(projection) {}

std::vector<std::uint8_t> WaterMask::of(const Aabb& lonLat) const {
  constexpr auto kCells = static_cast<std::size_t>(kSize) * kSize;
  const Vec2 cell = lonLat.size() * (1.0 / kSize);
  std::vector<double> lons(kSize), lats(kSize);
  for (int k = 0; k < kSize; ++k) {
    lons[static_cast<std::size_t>(k)] = lonLat.min.x + (k + 0.5) * cell.x;
    lats[static_cast<std::size_t>(k)] = lonLat.max.y - (k + 0.5) * cell.y;
  }
  std::vector<Vec2> cells;
  projection_.forwardGrid(lons, lats, cells);
  const Aabb box = boundsOf(cells);

  const geometry::PolygonIndex& land = world_.land();
  const geometry::PolygonIndex::Clearance clear =
      box.intersects(land.bounds()) ? land.clearance(box)
                                    : geometry::PolygonIndex::Clearance{1.0, false};
  if (clear.distance > 0.0 && !clear.inside)
    return {kWater}; // all sea or all lake
  std::vector<std::uint8_t> mask(kCells, 0);
  if (clear.distance <= 0.0)
    for (std::size_t i = 0; i < kCells; ++i)
      mask[i] = land.contains(cells[i]) ? 0 : kWater;
  addRivers(lonLat, cells, mask);
  if (std::all_of(mask.begin(), mask.end(), [&](std::uint8_t v) { return v == mask[0]; }))
    return {mask[0]};
  return mask;
}

void WaterMask::addRivers(const Aabb& lonLat, const std::vector<Vec2>& cells,
                          std::vector<std::uint8_t>& mask) const {
  // A river shows when it is at least one cell wide: the cell's side, as the mean of its
  // north-south and (at the box's middle latitude) east-west extents.
  const Vec2 cellDegrees = lonLat.size() * (1.0 / kSize);
  const double middle = lonLat.center().y * kRadiansPerDegree;
  const double cellMetres = 0.5 * geometry::kEarthRadius * kRadiansPerDegree *
                            (cellDegrees.y + cellDegrees.x * std::cos(middle));
  const Aabb box = boundsOf(cells);
  const auto& rivers = world_.data().rivers;
  for (std::size_t r = 0; r < rivers.size(); ++r) {
    const primitives::RiverPrimitive& river = rivers[r];
    if (std::max(river.widthUp, river.widthDown) < cellMetres ||
        !world_.riverSupport(base::PrimitiveId(static_cast<std::uint32_t>(r))).intersects(box))
      continue;
    // Width varies linearly along the curve with the distance travelled.
    double length = 0.0;
    for (std::size_t k = 1; k < river.curve.size(); ++k)
      length += geometry::distance(river.curve[k].position, river.curve[k - 1].position);
    double travelled = 0.0;
    for (std::size_t k = 1; k < river.curve.size(); ++k) {
      const Vec2 a = river.curve[k - 1].position, b = river.curve[k].position;
      const double step = geometry::distance(a, b);
      const double t = length > 0.0 ? (travelled + 0.5 * step) / length : 0.0;
      travelled += step;
      const double half = 0.5 * (river.widthUp + t * (river.widthDown - river.widthUp));
      if (2.0 * half < cellMetres)
        continue;
      Aabb segment;
      segment.add(a);
      segment.add(b);
      segment = segment.expanded(half);
      if (!segment.intersects(box))
        continue;
      // The cells the segment's box may cover: its corners' longitudes and latitudes, one
      // cell of margin for the projection's curvature.
      Aabb corners;
      for (Vec2 c : {segment.min, segment.max, Vec2{segment.min.x, segment.max.y},
                     Vec2{segment.max.x, segment.min.y}})
        corners.add(projection_.inverse(c));
      const auto index = [](double v) {
        return static_cast<int>(std::clamp(std::floor(v), -1.0, double{kSize}));
      };
      const int i0 = std::max(0, index((corners.min.x - lonLat.min.x) / cellDegrees.x) - 1);
      const int i1 = std::min(kSize - 1, index((corners.max.x - lonLat.min.x) / cellDegrees.x) + 1);
      const int j0 = std::max(0, index((lonLat.max.y - corners.max.y) / cellDegrees.y) - 1);
      const int j1 = std::min(kSize - 1, index((lonLat.max.y - corners.min.y) / cellDegrees.y) + 1);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const auto c = static_cast<std::size_t>(j) * kSize + static_cast<std::size_t>(i);
          if (mask[c] != kWater && distance2ToSegment(cells[c], a, b) <= half * half)
            mask[c] = kWater;
        }
    }
  }
}

} // namespace strahler::tiling
