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

  /// Calls fn(first, last) for the slots [first, last) of order of each row of the 3 × 3 cells
  /// around p (a row's cells are contiguous in order), until fn returns false; false when it
  /// did.
  template <class Fn> bool forNeighbourRows(Vec2 p, Fn&& fn) const {
    const std::int64_t x = cellX(p.x), y = cellY(p.y);
    const std::int64_t x0 = std::max<std::int64_t>(x - 1, 0), x1 = std::min(x + 1, nx - 1);
    for (std::int64_t yy = std::max<std::int64_t>(y - 1, 0); yy <= std::min(y + 1, ny - 1); ++yy)
      if (!fn(start[static_cast<std::size_t>(yy * nx + x0)],
              start[static_cast<std::size_t>(yy * nx + x1 + 1)]))
        return false;
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
  // The plants' state in grid order (slot k is plants[order[k]]), for contiguous scans.
  const std::size_t n = plants.size();
  std::vector<Vec2> position(n);
  std::vector<double> radius(n, 0.0);
  std::vector<std::uint8_t> alive(n);
  for (std::size_t k = 0; k < n; ++k) {
    position[k] = plants[grid.order[k]].position;
    alive[k] = plants[grid.order[k]].alive;
  }
  std::vector<std::size_t> killed;
  for (int step = 0; step < steps; ++step) {
    for (std::size_t k = 0; k < n; ++k) {
      Plant& p = plants[grid.order[k]];
      if (!alive[k])
        continue;
      ++p.age;
      radius[k] = kSpecies[p.species].radiusAt(p.age);
      alive[k] = p.age <= kSpecies[p.species].maxAge;
    }
    // The seed's competition (004, 2.3.2), all at once: the larger of two plants kills the
    // smaller when the smaller stands strictly inside its radius; equal radii both live.
    killed.clear();
    for (std::size_t j = 0; j < n; ++j) {
      if (!alive[j] || radius[j] >= reach)
        continue; // nothing outgrows the largest radius
      const double rj = radius[j];
      const Vec2 pj = position[j];
      const bool lives = grid.forNeighbourRows(pj, [&](std::size_t first, std::size_t last) {
        bool beaten = false;
        for (std::size_t k = first; k < last; ++k) // branch-free: the tests are coin flips
          beaten |= (alive[k] != 0) & (radius[k] > rj) &
                    (geometry::lengthSquared(position[k] - pj) < radius[k] * radius[k]);
        return !beaten;
      });
      if (!lives)
        killed.push_back(j);
    }
    for (std::size_t j : killed)
      alive[j] = 0;
  }
  for (std::size_t k = 0; k < n; ++k)
    plants[grid.order[k]].alive = alive[k] != 0;
}

} // namespace strahler::vegetation
