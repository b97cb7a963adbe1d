#include "strahler/quality/world_raster.h"

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

namespace strahler::quality {
namespace {

/// The raster's extent: the land's bounds and a kilometre of sea around them.
geometry::Aabb rasterBounds(const construction::World& world) {
  return world.land().bounds().expanded(1000.0);
}

using geometry::Vec2;

/// The class of the cell of side `cellSize` centred on p.
CellClass classify(const construction::World& world, Vec2 p, double cellSize) {
  if (world.land().contains(p))
    return world.land().distanceToBoundary(p, 0.5 * cellSize) < 0.5 * cellSize ? CellClass::kShore
                                                                               : CellClass::kLand;
  for (const geometry::Polygon& poly : world.data().land)
    if (geometry::contains(poly.outer, p))
      return CellClass::kLake;
  return CellClass::kSea;
}

void sampleRows(const construction::World& world, HeightRaster& r, int first, int step) {
  std::vector<Vec2> points(static_cast<std::size_t>(r.width));
  std::vector<double> heights(points.size());
  for (int y = first; y < r.height; y += step) {
    for (int x = 0; x < r.width; ++x)
      points[static_cast<std::size_t>(x)] = r.origin + Vec2{x * r.cellSize, y * r.cellSize};
    world.heights(points, r.cellSize, heights);
    for (int x = 0; x < r.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(r.width) +
                            static_cast<std::size_t>(x);
      r.heights[i] = static_cast<float>(heights[static_cast<std::size_t>(x)]);
      r.cellClass[i] = static_cast<std::uint8_t>(
          classify(world, points[static_cast<std::size_t>(x)], r.cellSize));
    }
  }
}

} // namespace

void burnRivers(const construction::World& world, HeightRaster& r) {
  const Vec2 corner = r.origin - Vec2{0.5 * r.cellSize, 0.5 * r.cellSize};
  for (const std::vector<Vec2>& line : riverCentrelines(world))
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
      const Vec2 a = line[k], b = line[k + 1];
      // Half-cell steps, so consecutive samples fall in 8-connected cells.
      const int steps = static_cast<int>(std::ceil(distance(a, b) / (0.5 * r.cellSize))) + 1;
      for (int j = 0; j <= steps; ++j) {
        const Vec2 q = lerp(a, b, static_cast<double>(j) / steps);
        const int cx = static_cast<int>(std::floor((q.x - corner.x) / r.cellSize));
        const int cy = static_cast<int>(std::floor((q.y - corner.y) / r.cellSize));
        if (cx < 0 || cy < 0 || cx >= r.width || cy >= r.height)
          continue;
        const std::size_t i = static_cast<std::size_t>(cy) * static_cast<std::size_t>(r.width) +
                              static_cast<std::size_t>(cx);
        r.heights[i] = std::min(r.heights[i], static_cast<float>(world.height(q, r.cellSize)));
      }
    }
}

double worldRasterCells(const construction::World& world, double cellSize) {
  const geometry::Aabb box = rasterBounds(world);
  return (std::floor(box.size().x / cellSize) + 1.0) * (std::floor(box.size().y / cellSize) + 1.0);
}

HeightRaster rasterizeWorld(const construction::World& world, double cellSize, int threads,
                            RiverBurning burning) {
  const geometry::Aabb box = rasterBounds(world);
  HeightRaster r;
  r.cellSize = cellSize;
  r.width = static_cast<int>(box.size().x / cellSize) + 1;
  r.height = static_cast<int>(box.size().y / cellSize) + 1;
  r.origin = box.min + Vec2{0.5 * cellSize, 0.5 * cellSize};
  r.heights.resize(static_cast<std::size_t>(r.width) * static_cast<std::size_t>(r.height));
  r.cellClass.resize(r.heights.size());
  std::vector<std::thread> pool;
  const int n = std::max(1, threads);
  for (int t = 1; t < n; ++t)
    pool.emplace_back([&, t] { sampleRows(world, r, t, n); });
  sampleRows(world, r, 0, n);
  for (std::thread& t : pool)
    t.join();
  if (burning == RiverBurning::kBurn)
    burnRivers(world, r);
  return r;
}

std::vector<Vec2> riverCentreline(const construction::World& world,
                                  const primitives::RiverPrimitive& river) {
  std::vector<Vec2> line;
  for (const primitives::CurvePoint& p : river.curve) {
    line.push_back(p.position);
    if (line.size() > 1 && !world.land().contains(p.position))
      break; // reached the water
  }
  return line;
}

std::vector<std::vector<Vec2>> riverCentrelines(const construction::World& world) {
  std::vector<std::vector<Vec2>> lines;
  for (const primitives::RiverPrimitive& river : world.data().rivers) {
    std::vector<Vec2> line = riverCentreline(world, river);
    if (line.size() >= 2)
      lines.push_back(std::move(line));
  }
  return lines;
}

} // namespace strahler::quality
