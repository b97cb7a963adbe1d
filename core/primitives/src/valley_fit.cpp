#include "strahler/primitives/quantization.h"
#include "strahler/primitives/river_primitives.h"
#include "strahler/primitives/terrain_primitives.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace strahler::primitives {
namespace {

using geometry::Vec2;

/// Cell side of the grid of terrain primitive centres, m.
constexpr double kCell = 256.0;
/// Margin on the estimated rise (relief octaves and the primitives' planes reach a little higher
/// than the centres' elevations).
constexpr double kRiseMargin = 1.15;

/// The terrain primitives' centres binned in square cells.
class CentreGrid {
public:
  explicit CentreGrid(const std::vector<TerrainPrimitive>& terrain) : terrain_(terrain) {
    for (std::uint32_t i = 0; i < terrain.size(); ++i)
      cells_[key(cellOf(terrain[i].center.x), cellOf(terrain[i].center.y))].push_back(i);
  }

  /// The greatest elevation of a primitive centred within `reach` of p (−∞ if none).
  double highestWithin(Vec2 p, double reach) const {
    double best = -INFINITY;
    const std::int64_t x0 = cellOf(p.x - reach), x1 = cellOf(p.x + reach);
    const std::int64_t y0 = cellOf(p.y - reach), y1 = cellOf(p.y + reach);
    for (std::int64_t y = y0; y <= y1; ++y)
      for (std::int64_t x = x0; x <= x1; ++x) {
        const auto found = cells_.find(key(x, y));
        if (found == cells_.end())
          continue;
        for (const std::uint32_t i : found->second)
          if (lengthSquared(terrain_[i].center - p) <= reach * reach)
            best = std::max(best, terrain_[i].elevation);
      }
    return best;
  }

private:
  static std::int64_t cellOf(double v) { return static_cast<std::int64_t>(std::floor(v / kCell)); }
  static std::uint64_t key(std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(x) << 32) ^ static_cast<std::uint32_t>(y);
  }

  const std::vector<TerrainPrimitive>& terrain_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

} // namespace

double valleyMinReach(RiverType type, double widthUp, double widthDown) noexcept {
  return 0.5 * valleyRadius(type, std::max(widthUp, widthDown));
}

void fitValleyRadii(std::vector<RiverPrimitive>& rivers,
                    const std::vector<TerrainPrimitive>& terrain) {
  const CentreGrid grid(terrain);
  const double terrainRadius = kTerrainRadiusInSpacings * kTerrainSpacing;
  for (RiverPrimitive& r : rivers) {
    const double minReach = valleyMinReach(r.type, r.widthUp, r.widthDown);
    double rise = 0.0;
    for (const CurvePoint& p : r.curve)
      rise = std::max(rise,
                      grid.highestWithin(p.position, r.radius + 0.5 * terrainRadius) - p.elevation);
    const double needed = kValleyRunPerRise * kRiseMargin * rise;
    const double fitted = std::min(std::max(needed, minReach), r.radius);
    r.radius = std::min(r.radius, std::ceil(fitted / Quantum::kRadius) * Quantum::kRadius);
  }
}

} // namespace strahler::primitives
