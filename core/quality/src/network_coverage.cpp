#include "strahler/quality/network_coverage.h"

#include "strahler/geometry/distance_transform.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace strahler::quality {

NetworkCoverage networkCoverage(const network::RiverNetwork& network,
                                const geometry::PolygonIndex& land, double cellSize) {
  constexpr double kMaxCells = double(std::size_t{1} << 24);
  NetworkCoverage c;
  const geometry::Aabb box = land.bounds();
  const geometry::Vec2 size = box.size();
  double cell = std::max(cellSize, 1.0);
  while ((size.x / cell + 1.0) * (size.y / cell + 1.0) > kMaxCells)
    cell *= 1.5;
  c.cellSize = cell;
  const int width = static_cast<int>(size.x / cell) + 1;
  const int height = static_cast<int>(size.y / cell) + 1;
  std::vector<std::uint8_t> onRiver(std::size_t(width) * std::size_t(height), 0);
  bool anyEdge = false;
  const auto mark = [&](geometry::Vec2 p) {
    const auto x = static_cast<int>(std::floor((p.x - box.min.x) / cell));
    const auto y = static_cast<int>(std::floor((p.y - box.min.y) / cell));
    if (x >= 0 && y >= 0 && x < width && y < height)
      onRiver[std::size_t(y) * std::size_t(width) + std::size_t(x)] = 1;
  };
  for (const network::RiverNode& n : network.nodes) {
    if (!n.parent.valid())
      continue;
    anyEdge = true;
    const geometry::Vec2 a = network.node(n.parent).position;
    const int steps =
        std::max(1, static_cast<int>(std::ceil(2.0 * distance(a, n.position) / cell)));
    for (int k = 0; k <= steps; ++k)
      mark(geometry::lerp(a, n.position, double(k) / steps));
  }
  if (!anyEdge)
    return c;
  const std::vector<float> d = geometry::distanceToMarked(width, height, cell, onRiver);
  std::size_t landCells = 0, far = 0;
  double farthest = -1.0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const geometry::Vec2 p = box.min + geometry::Vec2{(x + 0.5) * cell, (y + 0.5) * cell};
      if (!land.contains(p))
        continue;
      const double v = d[std::size_t(y) * std::size_t(width) + std::size_t(x)];
      ++landCells;
      far += v > 3000.0 ? 1 : 0;
      if (v > farthest) {
        farthest = v;
        c.farthestAt = p;
      }
    }
  if (landCells == 0)
    return c;
  c.farthestM = farthest;
  c.fartherThan3KmFraction = double(far) / double(landCells);
  return c;
}

} // namespace strahler::quality
