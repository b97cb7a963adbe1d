#include "strahler/construction/world.h"

#include "evaluation_lanes.h"

#include "strahler/base/lanes.h"
#include "strahler/geometry/distance.h"
#include "strahler/primitives/river_primitives.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace strahler::construction {
namespace {

using geometry::Vec2;

constexpr double kGridCell = 500.0; // m
constexpr std::uint64_t kNoiseStream = 0x746572726e6full;
constexpr double kShelfReach = 4.0 * CoastShape::kShelfWidth;

double smoothstep(double t) noexcept {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

geometry::Aabb worldBounds(const WorldData& data) {
  geometry::Aabb box = geometry::bounds(data.land);
  for (const primitives::TerrainPrimitive& t : data.terrain)
    box.add(geometry::Aabb{t.center, t.center}.expanded(t.radius));
  for (const primitives::RiverPrimitive& r : data.rivers)
    box.add(primitives::supportBox(r));
  if (box.empty())
    box.add(Vec2{0, 0});
  return box;
}

} // namespace

double octaveFade(double wavelength, double spacing) noexcept {
  if (spacing <= 0.0)
    return 1.0;
  return std::clamp(wavelength / spacing * 0.5 - 1.0, 0.0, 1.0);
}

World::World(WorldData data)
    : data_(std::move(data)), land_(data_.land), terrainGrid_(worldBounds(data_), kGridCell),
      riverGrid_(worldBounds(data_), kGridCell), noise_(data_.params.seed ^ kNoiseStream) {
  hot_.reserve(data_.terrain.size());
  for (std::uint32_t i = 0; i < data_.terrain.size(); ++i) {
    const primitives::TerrainPrimitive& t = data_.terrain[i];
    const double radius2 = t.radius * t.radius;
    hot_.push_back({t.center, radius2, radius2 > 0.0 ? 1.0 / radius2 : 0.0, t.elevation,
                    std::max(t.amplitude, 0.0), std::clamp(t.roughness, 0.0, kMaxRoughness)});
    terrainGrid_.insert(geometry::Aabb{t.center, t.center}.expanded(t.radius), i);
  }
  for (std::uint32_t i = 0; i < data_.rivers.size(); ++i) {
    riverSupport_.push_back(primitives::supportBox(data_.rivers[i]));
    const std::vector<primitives::CurvePoint>& curve = data_.rivers[i].curve;
    std::vector<geometry::Aabb> chunks;
    for (std::size_t k = 0; k + 1 < curve.size(); k += detail::kChunk) {
      geometry::Aabb box;
      for (std::size_t j = k; j <= std::min(k + detail::kChunk, curve.size() - 1); ++j)
        box.add(curve[j].position);
      chunks.push_back(box);
    }
    riverChunks_.push_back(std::move(chunks));
    riverGrid_.insert(riverSupport_.back(), i);
  }
}

void World::terrainLanes(std::size_t lanes, const double* xs, const double* ys, double spacing,
                         std::span<const std::uint32_t> ids, double* h, double* w) const noexcept {
  // The octaves that survive the LOD fade at this spacing (they get shorter, so a prefix)
  // and their fades: each costs a division, and callers sweep rows of equal spacing, so they
  // are kept per thread for the last spacing seen (a pure function of it: same values).
  thread_local detail::OctaveFades fades{std::numeric_limits<double>::quiet_NaN(), 0, {}};
  if (!(fades.spacing == spacing)) {
    int active = 0;
    for (double wavelength = NoiseOctaves::kLongest;
         active < NoiseOctaves::kOctaves && octaveFade(wavelength, spacing) > 0.0;
         wavelength *= 0.5) {
      fades.fade[static_cast<std::size_t>(active)] = octaveFade(wavelength, spacing);
      ++active;
    }
    fades.active = active;
    fades.spacing = spacing;
  }
  const detail::TerrainLaneArgs args{hot_.data(), ids, &fades, &noise_, xs, ys, h, w};
  if (lanes == 1)
    detail::terrainPoint(args);
  else
    detail::terrainLanes(args);
}

void World::riversLanes(std::size_t lanes, const double* xs, const double* ys,
                        std::span<const std::uint32_t> ids, Sample* out) const noexcept {
  constexpr auto kLanes = static_cast<std::size_t>(base::kLanes);
  std::array<double, kLanes> distance, elevation, along;
  std::array<std::int64_t, kLanes> active;
  for (std::size_t l = 0; l < lanes; ++l)
    out[l] = {};
  for (const std::uint32_t i : ids) {
    bool any = false;
    for (std::size_t l = 0; l < lanes; ++l) {
      active[l] = riverSupport_[i].contains({xs[l], ys[l]}) ? -1 : 0;
      any = any || active[l] != 0;
    }
    if (!any)
      continue;
    const primitives::RiverPrimitive& r = data_.rivers[i];
    const detail::CurveLaneArgs args{
        &r,          riverChunks_[i], xs, ys, active.data(), distance.data(), elevation.data(),
        along.data()};
    if (lanes == 1)
      detail::closestOnCurvePoint(args);
    else
      detail::closestOnCurveLanes(args);
    for (std::size_t l = 0; l < lanes; ++l) {
      if (active[l] == 0)
        continue;
      const double d = distance[l];
      const double w = primitives::falloff(d * d, r.radius * r.radius);
      if (w <= 0.0)
        continue;
      const double width = r.widthUp + (r.widthDown - r.widthUp) * along[l];
      const double depth = r.depthUp + (r.depthDown - r.depthUp) * along[l];
      const Sample s{elevation[l] + primitives::riverProfile(r.type, width, depth, d), w};
      out[l] = out[l].w > 0.0 ? uniteByInfluence(out[l], s) : s;
    }
  }
}

double World::shelfReach() noexcept {
  return kShelfReach;
}

double World::shapeCoast(Vec2 p, const Sample& terrain, const Sample& rivers,
                         Coast coast) const noexcept {
  // Rivers keep their own bed (monotone downstream); only the terrain gets the beach ramp.
  // Both are capped by a surface that is 0 at the shore, so land and sea meet at 0 m,
  // river mouths included.
  if (coast != Coast::kFarSea && land_.contains(p)) {
    const double d = land_.distanceToBoundary(p, CoastShape::kBand);
    if (d >= CoastShape::kBand)
      return replace(terrain, rivers).h;
    const double t = smoothstep(d / CoastShape::kBand);
    const double ground = terrain.w > 0.0 ? terrain.h : rivers.h;
    const Sample shaped{t * ground + (1.0 - t) * std::min(ground, CoastShape::kBeachSlope * d),
                        terrain.w};
    // A 45° cap near the shore that rises out of reach (×11) by the end of the band.
    const double cap = d * (1.0 + 10.0 * t * t);
    return replace(shaped, {std::min(rivers.h, cap), rivers.w}).h;
  }
  const double d = coast == Coast::kFarSea ? kShelfReach : land_.distanceToBoundary(p, kShelfReach);
  const double sea = -CoastShape::kShelfDepth * (1.0 - std::exp(-d / CoastShape::kShelfWidth));
  return replace({sea, 1.0}, {std::min(rivers.h, sea), rivers.w}).h;
}

World::Evaluation World::evaluate(Vec2 p, double spacing) const noexcept {
  return evaluateFrom(p, spacing, terrainGrid_.cellAt(p), riverGrid_.cellAt(p));
}

World::Evaluation World::evaluateFrom(Vec2 p, double spacing,
                                      std::span<const std::uint32_t> terrain,
                                      std::span<const std::uint32_t> rivers,
                                      Coast coast) const noexcept {
  double h = 0.0, w = 0.0;
  Sample river;
  terrainLanes(1, &p.x, &p.y, spacing, terrain, &h, &w);
  riversLanes(1, &p.x, &p.y, rivers, &river);
  Evaluation e;
  e.terrain = {h, w};
  e.rivers = river;
  e.tree = replace(e.terrain, e.rivers).h;
  e.height = coast == Coast::kInland ? e.tree : shapeCoast(p, e.terrain, e.rivers, coast);
  return e;
}

void World::heights(std::span<const Vec2> points, double spacing,
                    std::span<double> out) const noexcept {
  constexpr auto kLanes = static_cast<std::size_t>(base::kLanes);
  for (std::size_t begin = 0; begin < points.size(); begin += kLanes) {
    const std::span<const Vec2> group =
        points.subspan(begin, std::min(kLanes, points.size() - begin));
    const std::vector<std::uint32_t>& terrain = terrainGrid_.cellAt(group[0]);
    const std::vector<std::uint32_t>& rivers = riverGrid_.cellAt(group[0]);
    const bool shared = std::all_of(group.begin(), group.end(), [&](Vec2 p) {
      return &terrainGrid_.cellAt(p) == &terrain && &riverGrid_.cellAt(p) == &rivers;
    });
    if (shared) {
      heightsFrom(group, spacing, terrain, rivers, Coast::kUnknown,
                  out.subspan(begin, group.size()));
      continue;
    }
    for (std::size_t l = 0; l < group.size(); ++l)
      out[begin + l] = height(group[l], spacing);
  }
}

void World::heightsFrom(std::span<const Vec2> points, double spacing,
                        std::span<const std::uint32_t> terrain,
                        std::span<const std::uint32_t> rivers, Coast coast,
                        std::span<double> heights) const noexcept {
  constexpr auto kLanes = static_cast<std::size_t>(base::kLanes);
  std::array<double, kLanes> xs, ys, h, w;
  std::array<Sample, kLanes> river;
  for (std::size_t begin = 0; begin < points.size(); begin += kLanes) {
    const std::size_t n = std::min(kLanes, points.size() - begin);
    for (std::size_t l = 0; l < kLanes; ++l) { // short groups repeat their last point
      const Vec2 p = points[begin + std::min(l, n - 1)];
      xs[l] = p.x;
      ys[l] = p.y;
    }
    terrainLanes(kLanes, xs.data(), ys.data(), spacing, terrain, h.data(), w.data());
    riversLanes(kLanes, xs.data(), ys.data(), rivers, river.data());
    for (std::size_t l = 0; l < n; ++l) {
      const Vec2 p = points[begin + l];
      const Sample t{h[l], w[l]};
      const Sample r = river[l];
      heights[begin + l] = coast == Coast::kInland ? replace(t, r).h : shapeCoast(p, t, r, coast);
    }
  }
}

} // namespace strahler::construction
