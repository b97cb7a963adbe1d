#include "world_bounds.h"

#include "strahler/geometry/aabb.h"
#include "strahler/geometry/projection.h"

namespace strahler::app {

LonLatBox worldBounds(const construction::WorldData& world) {
  const geometry::LocalProjection projection(world.projectionCenter.x, world.projectionCenter.y);
  geometry::Aabb box;
  for (const geometry::Polygon& p : world.land)
    for (geometry::Vec2 v : p.outer)
      box.add(projection.inverse(v));
  return {box.min.x, box.min.y, box.max.x, box.max.y};
}

} // namespace strahler::app
