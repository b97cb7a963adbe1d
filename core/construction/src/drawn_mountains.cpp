#include "drawn_mountains.h"

#include "strahler/primitives/drawn_relief.h"
#include "strahler/primitives/river_primitives.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace strahler::construction::detail {
namespace {

using geometry::Vec2;

/// Worlds built at most (the first at gain 1).
constexpr int kMaxRounds = 4;
/// A mountain within this share of its elevation is left as it is.
constexpr double kAim = 0.03;
/// Sample spacing of the summit search, m.
constexpr double kSummitSpacing = 40.0;
/// How far beyond kSummitReach the primitives of the fitting worlds reach, m.
constexpr double kContext = 1500.0;
/// Bounds of a mountain's gain.
constexpr double kMinGain = 0.1;
constexpr double kMaxGain = 10.0;

/// One mountain's secant search.
struct Search {
  double target = 0.0;
  double gain = 1.0, reached = 0.0;         // the last round
  double lastGain = 1.0, lastReached = 0.0; // the round before
  double bestGain = 1.0, bestMiss = std::numeric_limits<double>::infinity();
  bool done = true;
};

/// The primitives of `data` near the summits, with the index of each terrain primitive in
/// `data`: a world that evaluates like `data` within kSummitReach of them, and costs little.
struct Around {
  WorldData data;
  std::vector<std::size_t> terrainIndex;
};

Around around(const WorldData& data, const std::vector<Vec2>& summits) {
  const double reach = kSummitReach + kContext;
  auto near = [&](const geometry::Aabb& box) {
    return std::any_of(summits.begin(), summits.end(),
                       [&](Vec2 s) { return box.expanded(reach).contains(s); });
  };
  Around out;
  WorldData& d = out.data;
  d.name = data.name;
  d.params = data.params;
  d.projectionCenter = data.projectionCenter;
  d.land = data.land;
  d.network = data.network;
  d.flow = data.flow;
  d.riverTypes = data.riverTypes;
  d.features = data.features;
  for (const BlockPrimitives& block : data.blocks) {
    BlockPrimitives b;
    b.terrainBegin = static_cast<std::uint32_t>(d.terrain.size());
    for (std::uint32_t i = block.terrainBegin; i < block.terrainEnd; ++i) {
      const primitives::TerrainPrimitive& t = data.terrain[i];
      if (near(geometry::Aabb{t.center, t.center}.expanded(t.radius))) {
        d.terrain.push_back(t);
        out.terrainIndex.push_back(i);
      }
    }
    b.terrainEnd = static_cast<std::uint32_t>(d.terrain.size());
    b.riverBegin = static_cast<std::uint32_t>(d.rivers.size());
    for (std::uint32_t i = block.riverBegin; i < block.riverEnd; ++i)
      if (near(primitives::supportBox(data.rivers[i])))
        d.rivers.push_back(data.rivers[i]);
    b.riverEnd = static_cast<std::uint32_t>(d.rivers.size());
    d.blocks.push_back(b);
  }
  return out;
}

/// Each primitive of `terrain` scaled by the mountains' gains above its base (bases[i], one per
/// primitive), under the summits' cones.
void scaleAroundMountains(const input::Features& features, std::span<const double> radii,
                          std::span<const double> gains,
                          std::span<const primitives::TerrainBase> bases,
                          std::vector<primitives::TerrainPrimitive>& terrain) {
  for (std::size_t i = 0; i < terrain.size(); ++i) {
    const double g = primitives::mountainGain(features, radii, gains, terrain[i].center);
    if (g != 1.0)
      terrain[i] =
          primitives::scaleRelief(terrain[i], bases[i].elevation, g,
                                  primitives::mountainCap(features, radii, terrain[i].center));
  }
}

} // namespace

double highestWithin(const World& world, Vec2 p, double reach, double spacing) {
  double highest = -std::numeric_limits<double>::infinity();
  Vec2 at = p;
  std::vector<Vec2> row;
  std::vector<double> heights;
  auto scan = [&](Vec2 centre, double radius, double step) {
    const auto steps = static_cast<int>(std::floor(radius / step));
    for (int j = -steps; j <= steps; ++j) {
      row.clear();
      const double y = j * step;
      for (int i = -steps; i <= steps; ++i) {
        const Vec2 q = centre + Vec2{i * step, y};
        if (distance(q, p) <= reach)
          row.push_back(q);
      }
      heights.resize(row.size());
      world.heights(row, step, heights);
      for (std::size_t k = 0; k < row.size(); ++k)
        if (heights[k] > highest) {
          highest = heights[k];
          at = row[k];
        }
    }
  };
  scan(p, reach, spacing);
  scan(at, spacing, spacing / 4.0);
  return highest;
}

void fitDrawnMountains(const input::WorldSpec& spec, WorldData& data,
                       const std::vector<primitives::TerrainBase>& bases) {
  const input::Features& features = spec.features;
  const auto& mountains = features.mountains;
  std::vector<Search> searches(mountains.size());
  std::vector<Vec2> summits;
  for (std::size_t m = 0; m < mountains.size(); ++m)
    if (mountains[m].elevation) {
      searches[m].target = *mountains[m].elevation;
      searches[m].done = false;
      summits.push_back(mountains[m].position);
    }
  const std::vector<primitives::RiverPrimitive> unfitted = data.rivers;
  if (!summits.empty()) {
    const std::vector<double> radii = primitives::mountainRadii(spec);
    std::vector<double> gains(mountains.size(), 1.0);
    const Around near = around(data, summits);
    // The lowest river base near each summit: where the line H = b + g (H₁ − b) starts.
    std::vector<double> floors(mountains.size(), std::numeric_limits<double>::infinity());
    for (std::size_t i : near.terrainIndex)
      for (std::size_t m = 0; m < mountains.size(); ++m)
        if (distance(data.terrain[i].center, mountains[m].position) <= kSummitReach)
          floors[m] = std::min(floors[m], bases[i].elevation);
    std::vector<primitives::TerrainBase> nearBases;
    for (std::size_t i : near.terrainIndex)
      nearBases.push_back(bases[i]);
    for (int round = 0; round < kMaxRounds; ++round) {
      WorldData scaled = near.data;
      scaleAroundMountains(features, radii, gains, nearBases, scaled.terrain);
      primitives::liftCrests(spec, scaled.terrain, nearBases);
      primitives::fitValleyRadii(scaled.rivers, scaled.terrain);
      primitives::keepValleysOffCrests(spec, scaled.rivers);
      const World world(std::move(scaled));
      bool allDone = true;
      for (std::size_t m = 0; m < mountains.size(); ++m) {
        Search& s = searches[m];
        if (s.done)
          continue;
        s.reached = highestWithin(world, mountains[m].position, kSummitReach, kSummitSpacing);
        const double miss = std::abs(s.reached - s.target);
        if (miss < s.bestMiss) {
          s.bestMiss = miss;
          s.bestGain = s.gain;
        }
        if (miss <= kAim * s.target) {
          s.done = true;
          continue;
        }
        allDone = false;
        double next;
        if (round == 0) {
          const double floor = std::isfinite(floors[m]) ? std::min(floors[m], s.reached) : 0.0;
          next = s.reached - floor > 1.0 ? (s.target - floor) / (s.reached - floor)
                                         : s.target / std::max(s.reached, 1.0);
        } else {
          const double rise = s.reached - s.lastReached;
          next = std::abs(rise) > 1e-6
                     ? s.gain + (s.target - s.reached) * (s.gain - s.lastGain) / rise
                     : s.gain * s.target / std::max(s.reached, 1.0);
        }
        s.lastGain = s.gain;
        s.lastReached = s.reached;
        s.gain = std::clamp(next, kMinGain, kMaxGain);
        gains[m] = s.gain;
      }
      if (allDone)
        break;
    }
    // Each mountain's best measured gain, on the whole world.
    for (std::size_t m = 0; m < mountains.size(); ++m)
      gains[m] = searches[m].bestGain;
    scaleAroundMountains(features, radii, gains, bases, data.terrain);
  }
  primitives::liftCrests(spec, data.terrain, bases);
  data.rivers = unfitted;
  primitives::fitValleyRadii(data.rivers, data.terrain);
  primitives::keepValleysOffCrests(spec, data.rivers);
}

} // namespace strahler::construction::detail
