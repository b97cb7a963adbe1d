#include "strahler/geometry/aabb.h"
#include "strahler/vegetation/placement.h"

#include <algorithm>
#include <cmath>

namespace strahler::vegetation {
namespace {

using geometry::Vec2;

/// The plants bucketed by a uniform grid of side ≥ the largest radius, so that every plant
/// that can reach a plant lies in the 3 × 3 cells around it.
struct PlantGrid {
  Vec2 origin;
  double cell = 1.0;
  std::int64_t nx = 1, ny = 1;
  std::vector<std::size_t> start; // cell c holds order[start[c] .. start[c + 1])
  std::vector<std::size_t> order;

  std::int64_t cellX(double x) const noexcept {
    return std::clamp(static_cast<std::int64_t>((x - origin.x) / cell), std::int64_t{0}, nx - 1);
  }
  std::int64_t cellY(double y) const noexcept {
    return std::clamp(static_cast<std::int64_t>((y - origin.y) / cell), std::int64_t{0}, ny - 1);
  }

  PlantGrid(const std::vector<Plant>& plants, double reach) {
    geometry::Aabb box;
    for (const Plant& p : plants)
      box.add(p.position);
    origin = box.min;
    cell = std::max(reach, 1e-6);
    // A coarser grid stays correct (the 3 × 3 cells still cover the reach); keep it small.
    const double cap = 4.0 * static_cast<double>(plants.size()) + 16.0;
    while ((box.size().x / cell + 1.0) * (box.size().y / cell + 1.0) > cap)
      cell *= 2.0;
    nx = static_cast<std::int64_t>(box.size().x / cell) + 1;
    ny = static_cast<std::int64_t>(box.size().y / cell) + 1;
    start.assign(static_cast<std::size_t>(nx * ny) + 1, 0);
    for (const Plant& p : plants)
      ++start[index(p.position) + 1];
    for (std::size_t c = 1; c < start.size(); ++c)
      start[c] += start[c - 1];
    order.resize(plants.size());
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < plants.size(); ++i)
      order[fill[index(plants[i].position)]++] = i;
  }

  std::size_t index(Vec2 p) const noexcept {
    return static_cast<std::size_t>(cellY(p.y) * nx + cellX(p.x));
  }

  /// Calls fn(i) for every plant i of the 3 × 3 cells around p, until fn returns false; false
  /// when it did.
  template <class Fn> bool forNeighbours(Vec2 p, Fn&& fn) const {
    const std::int64_t x = cellX(p.x), y = cellY(p.y);
    for (std::int64_t yy = std::max<std::int64_t>(y - 1, 0); yy <= std::min(y + 1, ny - 1); ++yy)
      for (std::int64_t xx = std::max<std::int64_t>(x - 1, 0); xx <= std::min(x + 1, nx - 1);
           ++xx) {
        const auto c = static_cast<std::size_t>(yy * nx + xx);
        for (std::size_t k = start[c]; k < start[c + 1]; ++k)
          if (!fn(order[k]))
            return false;
      }
    return true;
  }
};

} // namespace

void simulateGrowth(std::vector<Plant>& plants, int steps) {
  if (plants.empty() || steps <= 0)
    return;
  double reach = 0.0;
  for (const Plant& p : plants)
    reach = std::max(reach, kSpecies[p.species].maxRadius);
  const PlantGrid grid(plants, reach);
  std::vector<double> radius(plants.size());
  std::vector<std::size_t> killed;
  for (int step = 0; step < steps; ++step) {
    for (std::size_t i = 0; i < plants.size(); ++i) {
      Plant& p = plants[i];
      if (!p.alive)
        continue;
      ++p.age;
      radius[i] = kSpecies[p.species].radiusAt(p.age);
      p.alive = p.age <= kSpecies[p.species].maxAge;
    }
    // The seed's competition (004, 2.3.2), all at once: the larger of two plants kills the
    // smaller when the smaller stands strictly inside its radius; equal radii both live.
    killed.clear();
    for (std::size_t j = 0; j < plants.size(); ++j) {
      if (!plants[j].alive || radius[j] >= reach)
        continue; // nothing outgrows the largest radius
      const bool lives = grid.forNeighbours(plants[j].position, [&](std::size_t i) {
        return !(plants[i].alive && radius[i] > radius[j] &&
                 geometry::lengthSquared(plants[i].position - plants[j].position) <
                     radius[i] * radius[i]);
      });
      if (!lives)
        killed.push_back(j);
    }
    for (std::size_t j : killed)
      plants[j].alive = false;
  }
}

} // namespace strahler::vegetation
