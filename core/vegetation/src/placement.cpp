#include "strahler/vegetation/placement.h"

#include "strahler/base/assert.h"
#include "strahler/base/random.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::vegetation {
namespace {

using geometry::Vec2;

constexpr std::uint64_t kSalt = 0x7665676574617469ull; // "vegetati": vegetation's hash stream
/// Hash lanes: the values drawn from one candidate's hash.
enum Lane : std::uint64_t { kOffsetX = 1, kOffsetY, kAcceptance, kAge, kRotation, kScale };
/// Largest number of grid cells one species may span (a programmer error past it).
constexpr std::int64_t kMaxCells = std::int64_t{1} << 26;

/// The hash of a cell: (seed, species, cx, cy) chained; a candidate's is mixHash(cell, k).
std::uint64_t cellHash(std::uint64_t seed, std::size_t species, std::int64_t cx,
                       std::int64_t cy) noexcept {
  std::uint64_t h = base::mixHash(seed, kSalt);
  h = base::mixHash(h, species);
  h = base::mixHash(h, static_cast<std::uint64_t>(cx));
  return base::mixHash(h, static_cast<std::uint64_t>(cy));
}

/// Uniform in [0, 1) from lane `lane` of hash h.
double unit(std::uint64_t h, Lane lane) noexcept {
  return static_cast<double>(base::mixHash(h, lane) >> 11) * 0x1.0p-53;
}

/// One species' candidates over the cells of a region, in (cy, cx, k) order, so that the
/// index order agrees with the global key order in every region (the priority tie-break).
struct CandidateGrid {
  double cell = 1.0;
  std::int64_t cx0 = 0, cy0 = 0;
  std::int64_t nx = 0, ny = 0;
  std::vector<Vec2> points;
  std::vector<std::uint64_t> hashes;
  std::vector<std::uint8_t> state; // kUndecided, kAccepted, kDropped

  static constexpr std::uint8_t kUndecided = 0, kAccepted = 1, kDropped = 2;

  /// Calls fn(first, last) for the candidates [first, last) of each row of the 3 × 3 cells
  /// around candidate p's cell (a row's candidates are contiguous), until fn returns false;
  /// false when it did.
  template <class Fn> bool forNeighbourRows(std::size_t p, Fn&& fn) const {
    const auto c = static_cast<std::int64_t>(p / kCandidatesPerCell);
    const std::int64_t x = c % nx, y = c / nx;
    const std::int64_t x0 = std::max<std::int64_t>(x - 1, 0), x1 = std::min(x + 1, nx - 1);
    for (std::int64_t yy = std::max<std::int64_t>(y - 1, 0); yy <= std::min(y + 1, ny - 1); ++yy)
      if (!fn(static_cast<std::size_t>((yy * nx + x0) * kCandidatesPerCell),
              static_cast<std::size_t>((yy * nx + x1 + 1) * kCandidatesPerCell)))
        return false;
    return true;
  }
};

CandidateGrid makeCandidates(std::uint64_t seed, std::size_t species, const geometry::Aabb& box,
                             const DensityField& density) {
  CandidateGrid g;
  g.cell = kSpecies[species].spacing;
  g.cx0 = static_cast<std::int64_t>(std::floor(box.min.x / g.cell));
  g.cy0 = static_cast<std::int64_t>(std::floor(box.min.y / g.cell));
  g.nx = static_cast<std::int64_t>(std::floor(box.max.x / g.cell)) - g.cx0 + 1;
  g.ny = static_cast<std::int64_t>(std::floor(box.max.y / g.cell)) - g.cy0 + 1;
  STRAHLER_ASSERT(g.nx > 0 && g.ny > 0 && g.nx * g.ny <= kMaxCells, "vegetation region too big");
  const auto count = static_cast<std::size_t>(g.nx * g.ny * kCandidatesPerCell);
  g.points.resize(count);
  g.hashes.resize(count);
  std::size_t i = 0;
  for (std::int64_t y = 0; y < g.ny; ++y)
    for (std::int64_t x = 0; x < g.nx; ++x) {
      const std::int64_t cx = g.cx0 + x, cy = g.cy0 + y;
      const std::uint64_t cell = cellHash(seed, species, cx, cy);
      for (int k = 0; k < kCandidatesPerCell; ++k, ++i) {
        const std::uint64_t h = base::mixHash(cell, static_cast<std::uint64_t>(k));
        g.hashes[i] = h;
        g.points[i] = {(static_cast<double>(cx) + unit(h, kOffsetX)) * g.cell,
                       (static_cast<double>(cy) + unit(h, kOffsetY)) * g.cell};
      }
    }
  std::vector<float> d(count);
  density.sample(species, g.points, d);
  g.state.resize(count);
  for (i = 0; i < count; ++i)
    g.state[i] = unit(g.hashes[i], kAcceptance) < static_cast<double>(d[i])
                     ? CandidateGrid::kUndecided
                     : CandidateGrid::kDropped;
  return g;
}

/// The rounds of PlacementRules::dartRounds on one species' candidates.
void throwDarts(CandidateGrid& g, int rounds) {
  const double s2 = g.cell * g.cell;
  std::vector<std::size_t> undecided, winners;
  for (std::size_t i = 0; i < g.state.size(); ++i)
    if (g.state[i] == CandidateGrid::kUndecided)
      undecided.push_back(i);
  for (int round = 0; round < rounds && !undecided.empty(); ++round) {
    winners.clear();
    for (std::size_t p : undecided) {
      // p loses to an undecided q closer than the spacing that outranks it (the hash, then
      // the index, which follows the global key). Branch-free rows: the tests are coin flips.
      const std::uint64_t hp = g.hashes[p];
      const Vec2 pp = g.points[p];
      const bool best = g.forNeighbourRows(p, [&](std::size_t first, std::size_t last) {
        bool beaten = false;
        for (std::size_t q = first; q < last; ++q) {
          const std::uint64_t hq = g.hashes[q];
          const bool outranks = (hq > hp) | ((hq == hp) & (q > p));
          beaten |= (g.state[q] == CandidateGrid::kUndecided) & outranks &
                    (geometry::lengthSquared(g.points[q] - pp) < s2);
        }
        return !beaten;
      });
      if (best)
        winners.push_back(p);
    }
    for (std::size_t w : winners)
      g.state[w] = CandidateGrid::kAccepted;
    for (std::size_t w : winners) // w itself is accepted now, so it is not dropped
      g.forNeighbourRows(w, [&](std::size_t first, std::size_t last) {
        for (std::size_t q = first; q < last; ++q)
          if (g.state[q] == CandidateGrid::kUndecided &&
              geometry::lengthSquared(g.points[q] - g.points[w]) < s2)
            g.state[q] = CandidateGrid::kDropped;
        return true;
      });
    std::erase_if(undecided,
                  [&](std::size_t p) { return g.state[p] != CandidateGrid::kUndecided; });
  }
}

} // namespace

Footprint Footprint::box(const geometry::Aabb& bounds) {
  return {bounds, [bounds](Vec2 p) {
            return p.x >= bounds.min.x && p.x < bounds.max.x && p.y >= bounds.min.y &&
                   p.y < bounds.max.y;
          }};
}

double dependencyBorder(const PlacementRules& rules, SpeciesMask mask,
                        SpeciesIndex species) noexcept {
  double radius = 0.0;
  for (std::size_t i = 0; i < kSpecies.size(); ++i)
    if (mask & (SpeciesMask{1} << i))
      radius = std::max(radius, kSpecies[i].maxRadius);
  return rules.growthSteps * radius + 2.0 * rules.dartRounds * kSpecies[species].spacing;
}

bool instanceLess(const Instance& a, const Instance& b) noexcept {
  if (a.species != b.species)
    return a.species < b.species;
  if (a.position.y != b.position.y)
    return a.position.y < b.position.y;
  if (a.position.x != b.position.x)
    return a.position.x < b.position.x;
  return a.id < b.id;
}

std::vector<Instance> placeInstances(std::uint64_t seed, const Footprint& footprint,
                                     const DensityField& density, SpeciesMask mask,
                                     const PlacementRules& rules) {
  std::vector<Instance> out;
  if (mask == 0 || footprint.bounds.empty())
    return out;
  std::vector<Plant> plants;
  std::vector<std::uint64_t> hashes;
  for (std::size_t s = 0; s < kSpecies.size(); ++s) {
    if (!(mask & (SpeciesMask{1} << s)))
      continue;
    // One spacing more than the border: the cells meeting the grown box hold every candidate
    // closer than the border to the footprint, with margin for rounding of the box.
    const auto index = static_cast<SpeciesIndex>(s);
    const geometry::Aabb region =
        footprint.bounds.expanded(dependencyBorder(rules, mask, index) + kSpecies[s].spacing);
    CandidateGrid g = makeCandidates(seed, s, region, density);
    throwDarts(g, rules.dartRounds);
    for (std::size_t i = 0; i < g.state.size(); ++i)
      if (g.state[i] == CandidateGrid::kAccepted) {
        const int age = static_cast<int>(unit(g.hashes[i], kAge) * kSpecies[s].maxAge);
        plants.push_back({g.points[i], static_cast<SpeciesIndex>(s), age, true});
        hashes.push_back(g.hashes[i]);
      }
  }
  simulateGrowth(plants, rules.growthSteps);
  for (std::size_t i = 0; i < plants.size(); ++i) {
    const Plant& p = plants[i];
    if (!p.alive || !footprint.contains(p.position))
      continue;
    Instance inst;
    inst.position = p.position;
    inst.species = p.species;
    inst.radius = static_cast<float>(kSpecies[p.species].radiusAt(p.age));
    inst.rotation = static_cast<float>(unit(hashes[i], kRotation) * 2.0 * std::numbers::pi);
    inst.scale = static_cast<float>(0.8 + 0.4 * unit(hashes[i], kScale));
    inst.id = hashes[i];
    out.push_back(inst);
  }
  std::sort(out.begin(), out.end(), instanceLess);
  return out;
}

} // namespace strahler::vegetation
