#include "strahler/geometry/grid_index.h"
#include "strahler/primitives/quantization.h"
#include "strahler/primitives/river_primitives.h"
#include "strahler/primitives/terrain_primitives.h"

#include <algorithm>
#include <cmath>

namespace strahler::primitives {
namespace {

/// Cell side of the grid of terrain primitive centres, m.
constexpr double kCell = 256.0;
/// Margin on the estimated rise (relief octaves and the primitives' planes reach a little higher
/// than the centres' elevations).
constexpr double kRiseMargin = 1.15;

} // namespace

double valleyMinReach(RiverType type, double widthUp, double widthDown) noexcept {
  return 0.5 * valleyRadius(type, std::max(widthUp, widthDown));
}

void fitValleyRadii(std::vector<RiverPrimitive>& rivers,
                    const std::vector<TerrainPrimitive>& terrain) {
  geometry::Aabb bounds{{0.0, 0.0}, {0.0, 0.0}}; // a valid box when there is no terrain
  if (!terrain.empty())
    bounds = {terrain[0].center, terrain[0].center};
  for (const TerrainPrimitive& t : terrain)
    bounds.add(t.center);
  geometry::GridIndex centres(bounds, kCell);
  for (std::uint32_t i = 0; i < terrain.size(); ++i)
    centres.insert({terrain[i].center, terrain[i].center}, i);
  const double terrainRadius = kTerrainRadiusInSpacings * kTerrainSpacing;
  for (RiverPrimitive& r : rivers) {
    const double minReach = valleyMinReach(r.type, r.widthUp, r.widthDown);
    const double reach = r.radius + 0.5 * terrainRadius;
    double rise = 0.0;
    for (const CurvePoint& p : r.curve)
      centres.query(geometry::Aabb{p.position, p.position}.expanded(reach), [&](std::uint32_t i) {
        if (lengthSquared(terrain[i].center - p.position) <= reach * reach)
          rise = std::max(rise, terrain[i].elevation - p.elevation);
        return true;
      });
    const double needed = kValleyRunPerRise * kRiseMargin * rise;
    const double fitted = std::min(std::max(needed, minReach), r.radius);
    r.radius = std::min(r.radius, std::ceil(fitted / Quantum::kRadius) * Quantum::kRadius);
  }
}

} // namespace strahler::primitives
