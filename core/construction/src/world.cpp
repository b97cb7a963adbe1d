#include "strahler/construction/world.h"

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

/// Distance from p to a river curve, with the water elevation and the fraction along the
/// curve at the closest point.
struct CurveHit {
  double distance = std::numeric_limits<double>::infinity();
  double elevation = 0.0;
  double along = 0.0; // 0 upstream .. 1 downstream
};

/// Only points closer than the primitive's radius matter (w = 0 beyond), so segments whose
/// bounding box is farther than the best distance so far are skipped.
CurveHit closestOnCurve(const primitives::RiverPrimitive& r, Vec2 p) {
  CurveHit best;
  double bound2 = r.radius * r.radius;
  const std::size_t n = r.curve.size();
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const primitives::CurvePoint& a = r.curve[k];
    const primitives::CurvePoint& b = r.curve[k + 1];
    const double dx = std::max({std::min(a.position.x, b.position.x) - p.x, 0.0,
                                p.x - std::max(a.position.x, b.position.x)});
    const double dy = std::max({std::min(a.position.y, b.position.y) - p.y, 0.0,
                                p.y - std::max(a.position.y, b.position.y)});
    if (dx * dx + dy * dy >= bound2)
      continue;
    const Vec2 q = geometry::closestPointOnSegment(p, a.position, b.position);
    const double d2 = lengthSquared(p - q);
    if (d2 >= bound2)
      continue;
    bound2 = d2;
    const double span = distance(a.position, b.position);
    const double t = span > 0.0 ? distance(a.position, q) / span : 0.0;
    best.distance = std::sqrt(d2);
    best.elevation = a.elevation + (b.elevation - a.elevation) * t;
    best.along = (static_cast<double>(k) + t) / static_cast<double>(n - 1);
  }
  return best;
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
  for (std::uint32_t i = 0; i < data_.terrain.size(); ++i) {
    const primitives::TerrainPrimitive& t = data_.terrain[i];
    // Normalised so that the octave gains g^k sum to 1 over all octaves, whatever the spacing.
    const double g = t.roughness;
    noiseScale_.push_back(t.amplitude * (1.0 - g) / (1.0 - std::pow(g, NoiseOctaves::kOctaves)));
    terrainGrid_.insert(geometry::Aabb{t.center, t.center}.expanded(t.radius), i);
  }
  for (std::uint32_t i = 0; i < data_.rivers.size(); ++i) {
    riverSupport_.push_back(primitives::supportBox(data_.rivers[i]));
    riverGrid_.insert(riverSupport_.back(), i);
  }
}

Sample World::terrainAt(Vec2 p, double spacing, std::span<const std::uint32_t> ids) const noexcept {
  // Octaves that survive the LOD fade at this spacing (they get shorter, so a prefix).
  int active = 0;
  for (double wavelength = NoiseOctaves::kLongest;
       active < NoiseOctaves::kOctaves && octaveFade(wavelength, spacing) > 0.0; wavelength *= 0.5)
    ++active;
  double weight = 0.0, weightedHeight = 0.0;
  std::array<double, NoiseOctaves::kOctaves> octaveAmplitude{}; // Σ w_i a_i g_i^k / norm_i
  int count = 0;
  for (const std::uint32_t i : ids) {
    const primitives::TerrainPrimitive& t = data_.terrain[i];
    const double w = primitives::falloff(lengthSquared(p - t.center), t.radius * t.radius);
    if (w <= 0.0)
      continue;
    ++count;
    weight += w;
    weightedHeight += w * t.elevation;
    if (t.amplitude > 0.0) {
      const double g = t.roughness;
      double gain = w * noiseScale_[i];
      for (int k = 0; k < active; ++k, gain *= g)
        octaveAmplitude[static_cast<std::size_t>(k)] += gain;
    }
  }
  if (weight <= 0.0)
    return {};
  double noise = 0.0;
  double wavelength = NoiseOctaves::kLongest;
  for (int k = 0; k < active; ++k, wavelength *= 0.5) {
    const double amplitude = octaveAmplitude[static_cast<std::size_t>(k)] / weight;
    const double fade = octaveFade(wavelength, spacing);
    if (amplitude < 1e-3)
      continue;
    const Vec2 offset{37.1 * k, -11.7 * k};
    noise += fade * amplitude * noise_.at(p / wavelength + offset);
  }
  Sample s = blendSums(weightedHeight, weight, count);
  s.h += noise;
  return s;
}

Sample World::riversAt(Vec2 p, std::span<const std::uint32_t> ids) const noexcept {
  Sample best;
  for (const std::uint32_t i : ids) {
    if (!riverSupport_[i].contains(p))
      continue;
    const primitives::RiverPrimitive& r = data_.rivers[i];
    const CurveHit hit = closestOnCurve(r, p);
    const double w = primitives::falloff(hit.distance * hit.distance, r.radius * r.radius);
    if (w <= 0.0)
      continue;
    const double width = r.widthUp + (r.widthDown - r.widthUp) * hit.along;
    const double depth = r.depthUp + (r.depthDown - r.depthUp) * hit.along;
    const Sample s{hit.elevation + primitives::riverProfile(r.type, width, depth, hit.distance), w};
    best = best.w > 0.0 ? uniteByInfluence(best, s) : s;
  }
  return best;
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
  Evaluation e;
  e.terrain = terrainAt(p, spacing, terrain);
  e.rivers = riversAt(p, rivers);
  e.tree = replace(e.terrain, e.rivers).h;
  e.height = coast == Coast::kInland ? e.tree : shapeCoast(p, e.terrain, e.rivers, coast);
  return e;
}

} // namespace strahler::construction
