#include "strahler/tiling/water_mask.h"

#include "strahler/tiling/river_segments.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace strahler::tiling {
namespace {

using geometry::Aabb;
using geometry::Vec2;

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

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

std::optional<std::uint8_t> WaterMask::uniform(const Aabb& outline, double cell) const {
  const geometry::PolygonIndex& land = world_.land();
  const double reach = 0.5 * geometry::length(outline.size()) * (1.0 + 1e-9) + 1e-6;
  if (land.distanceToBoundary(outline.center(), reach) >= reach) {
    if (!land.contains(outline.center()))
      return kWater; // all sea or all lake
    if (!anyRiver(outline, cell))
      return std::uint8_t{0};
  }
  return std::nullopt;
}

std::vector<std::uint8_t> WaterMask::of(const Aabb& lonLat) const {
  constexpr auto kCells = static_cast<std::size_t>(kSize) * kSize;
  const double cell = cellMetres(lonLat);
  // A first look from the box's outline in the local frame (16 points a side, grown 1 %): no
  // shore in it and no river a cell wide decides most boxes without a cell.
  Aabb outline;
  for (int k = 0; k <= 16; ++k) {
    const double t = k / 16.0;
    const Vec2 size = lonLat.size();
    for (Vec2 p : {Vec2{lonLat.min.x + t * size.x, lonLat.min.y},
                   Vec2{lonLat.min.x + t * size.x, lonLat.max.y},
                   Vec2{lonLat.min.x, lonLat.min.y + t * size.y},
                   Vec2{lonLat.max.x, lonLat.min.y + t * size.y}})
      outline.add(projection_.forward(p));
  }
  outline = outline.expanded(0.01 * std::max(outline.size().x, outline.size().y));
  if (const auto all = uniform(outline, cell))
    return {*all};

  std::vector<double> lons(kSize), lats(kSize);
  for (int k = 0; k < kSize; ++k) {
    lons[static_cast<std::size_t>(k)] = lonLat.min.x + (k + 0.5) * lonLat.size().x / kSize;
    lats[static_cast<std::size_t>(k)] = lonLat.max.y - (k + 0.5) * lonLat.size().y / kSize;
  }
  std::vector<Vec2> cells;
  projection_.forwardGrid(lons, lats, cells);
  std::vector<std::uint8_t> mask(kCells, 0);
  addSeaAndLakes(cells, kSize, kSize, mask);
  addRivers(lonLat, cell, cells, mask);
  if (std::all_of(mask.begin(), mask.end(), [&](std::uint8_t v) { return v == mask[0]; }))
    return {mask[0]};
  return mask;
}

std::vector<std::uint8_t> WaterMask::ofGrid(const SampleGrid& grid) const {
  const auto count = static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height);
  const double finest = *std::min_element(grid.rowSpacing.begin(), grid.rowSpacing.end());
  const Aabb outline =
      grid.bounds.expanded(0.01 * std::max(grid.bounds.size().x, grid.bounds.size().y));
  if (const auto all = uniform(outline, finest))
    return std::vector<std::uint8_t>(count, *all);
  std::vector<std::uint8_t> mask(count, 0);
  addSeaAndLakes(grid.points, grid.width, grid.height, mask);
  const GridRows rows(grid);
  const auto width = static_cast<std::size_t>(grid.width);
  forEachRiverSegment(world_, grid.bounds, finest, 0.0, [&](const RiverSegment& s) {
    Aabb box;
    box.add(s.a);
    box.add(s.b);
    rows.forEachIn(box.expanded(s.halfWidth), [&](std::size_t j, std::size_t i) {
      // Per sample, by its own row's spacing, so that neighbouring tiles agree.
      const std::size_t k = j * width + i;
      if (2.0 * s.halfWidth >= grid.rowSpacing[j] &&
          distance2ToSegment(grid.points[k], s.a, s.b) <= s.halfWidth * s.halfWidth)
        mask[k] = kWater;
    });
  });
  return mask;
}

double WaterMask::cellMetres(const Aabb& lonLat) noexcept {
  const Vec2 cellDegrees = lonLat.size() * (1.0 / kSize);
  const double middle = lonLat.center().y * kRadiansPerDegree;
  return 0.5 * geometry::kEarthRadius * kRadiansPerDegree *
         (cellDegrees.y + cellDegrees.x * std::cos(middle));
}

bool WaterMask::anyRiver(const Aabb& local, double width) const {
  const auto& rivers = world_.data().rivers;
  for (std::size_t r = 0; r < rivers.size(); ++r)
    if (std::max(rivers[r].widthUp, rivers[r].widthDown) >= width &&
        world_.riverSupport(base::PrimitiveId(static_cast<std::uint32_t>(r))).intersects(local))
      return true;
  return false;
}

void WaterMask::addSeaAndLakes(const std::vector<Vec2>& cells, int width, int height,
                               std::vector<std::uint8_t>& mask) const {
  // Blocks of kBlock² cells with no shore near are filled whole; the others ask cell by cell.
  constexpr int kBlock = 16;
  const geometry::PolygonIndex& land = world_.land();
  for (int bj = 0; bj < height; bj += kBlock)
    for (int bi = 0; bi < width; bi += kBlock) {
      const auto at = [&](int i, int j) {
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
               static_cast<std::size_t>(i);
      };
      const int ei = std::min(bi + kBlock, width), ej = std::min(bj + kBlock, height);
      Aabb block;
      for (int j = bj; j < ej; ++j) {
        block.add(cells[at(bi, j)]);
        block.add(cells[at(ei - 1, j)]);
      }
      for (int i = bi; i < ei; ++i) {
        block.add(cells[at(i, bj)]);
        block.add(cells[at(i, ej - 1)]);
      }
      // No shore within the block's half diagonal of its centre: one side of it throughout.
      const Vec2 centre = block.center();
      const double reach = 0.5 * geometry::length(block.size()) * (1.0 + 1e-9) + 1e-6;
      const bool clear = land.distanceToBoundary(centre, reach) >= reach;
      const bool blockInside = clear && land.contains(centre);
      for (int j = bj; j < ej; ++j)
        for (int i = bi; i < ei; ++i) {
          const bool inside = clear ? blockInside : land.contains(cells[at(i, j)]);
          mask[at(i, j)] = inside ? 0 : kWater;
        }
    }
}

void WaterMask::addRivers(const Aabb& lonLat, double cellMetres, const std::vector<Vec2>& cells,
                          std::vector<std::uint8_t>& mask) const {
  const Vec2 cellDegrees = lonLat.size() * (1.0 / kSize);
  const Aabb box = boundsOf(cells);
  forEachRiverSegment(world_, box, cellMetres, 0.0, [&](const RiverSegment& s) {
    const Vec2 a = s.a, b = s.b;
    const double half = s.halfWidth;
    Aabb segment;
    segment.add(a);
    segment.add(b);
    segment = segment.expanded(half);
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
  });
}

} // namespace strahler::tiling
