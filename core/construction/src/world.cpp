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
/// Segments of a river curve per chunk box (see World::riverChunks_).
constexpr std::size_t kChunk = 8;

/// Squared distance from p to box [lo, hi] (0 inside).
double boxDistance2(Vec2 p, double loX, double loY, double hiX, double hiY) noexcept {
  const double dx = std::max({loX - p.x, 0.0, p.x - hiX});
  const double dy = std::max({loY - p.y, 0.0, p.y - hiY});
  return dx * dx + dy * dy;
}

/// `chunks` holds the box of each run of kChunk segments: a run whose box is no closer than
/// the bound is skipped whole, which skips exactly the segments the per-segment test would
/// (a segment's box lies inside its run's), so the result is unchanged.
CurveHit closestOnCurve(const primitives::RiverPrimitive& r, std::span<const geometry::Aabb> chunks,
                        Vec2 p) {
  CurveHit best;
  double bound2 = r.radius * r.radius;
  const std::size_t n = r.curve.size();
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (k % kChunk == 0) {
      const geometry::Aabb& c = chunks[k / kChunk];
      if (boxDistance2(p, c.min.x, c.min.y, c.max.x, c.max.y) >= bound2) {
        k += kChunk - 1;
        continue;
      }
    }
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
    const double scale = t.amplitude > 0.0
                             ? t.amplitude * (1.0 - g) / (1.0 - std::pow(g, NoiseOctaves::kOctaves))
                             : 0.0;
    hot_.push_back({t.center, t.radius * t.radius, t.elevation, scale});
    std::array<double, NoiseOctaves::kOctaves> gains{};
    double gain = scale;
    for (std::size_t k = 0; k < gains.size(); ++k, gain *= g)
      gains[k] = gain;
    octaveGains_.push_back(gains);
    terrainGrid_.insert(geometry::Aabb{t.center, t.center}.expanded(t.radius), i);
  }
  for (std::uint32_t i = 0; i < data_.rivers.size(); ++i) {
    riverSupport_.push_back(primitives::supportBox(data_.rivers[i]));
    const std::vector<primitives::CurvePoint>& curve = data_.rivers[i].curve;
    std::vector<geometry::Aabb> chunks;
    for (std::size_t k = 0; k + 1 < curve.size(); k += kChunk) {
      geometry::Aabb box;
      for (std::size_t j = k; j <= std::min(k + kChunk, curve.size() - 1); ++j)
        box.add(curve[j].position);
      chunks.push_back(box);
    }
    riverChunks_.push_back(std::move(chunks));
    riverGrid_.insert(riverSupport_.back(), i);
  }
}

template <int kActive>
World::Blend World::blend(Vec2 p, std::span<const std::uint32_t> ids) const noexcept {
  static_assert(kActive <= NoiseOctaves::kOctaves);
  Blend b;
  double weight = 0.0, weightedHeight = 0.0;
  std::array<double, kActive + 1> amplitude{}; // Σ w_i a_i g_i^k / norm_i (+1: never empty)
  int count = 0;
  const HotTerrain* hot = hot_.data();
  for (const std::uint32_t i : ids) {
    const HotTerrain& t = hot[i];
    const double w = primitives::falloff(lengthSquared(p - t.center), t.radius2);
    if (w <= 0.0)
      continue;
    ++count;
    weight += w;
    weightedHeight += w * t.elevation;
    if (t.noiseScale != 0.0) {
      // w · (a g^k / norm) with the per-primitive factors precomputed: independent products
      // that vectorise over k, instead of a chain of multiplications by g.
      const double* gains = octaveGains_[i].data();
      for (int k = 0; k < kActive; ++k)
        amplitude[static_cast<std::size_t>(k)] += w * gains[k];
    }
  }
  b.weight = weight;
  b.weightedHeight = weightedHeight;
  b.count = count;
  for (int k = 0; k < kActive; ++k)
    b.octaveAmplitude[static_cast<std::size_t>(k)] = amplitude[static_cast<std::size_t>(k)];
  return b;
}

Sample World::terrainAt(Vec2 p, double spacing, std::span<const std::uint32_t> ids) const noexcept {
  // Octaves that survive the LOD fade at this spacing (they get shorter, so a prefix), and
  // their fades. Each costs a division, and callers sweep rows of equal spacing, so they are
  // kept per thread for the last spacing seen (a pure function of it: same values).
  struct Fades {
    double spacing = std::numeric_limits<double>::quiet_NaN();
    int active = 0;
    std::array<double, NoiseOctaves::kOctaves> fade{};
  };
  thread_local Fades fades;
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
  const int active = fades.active;
  // The candidate loop, with the number of octaves fixed at compile time so the octave
  // sums stay in registers (same operations in the same order as a runtime loop).
  Blend b;
  switch (active) {
  case 0:
    b = blend<0>(p, ids);
    break;
  case 1:
    b = blend<1>(p, ids);
    break;
  case 2:
    b = blend<2>(p, ids);
    break;
  case 3:
    b = blend<3>(p, ids);
    break;
  case 4:
    b = blend<4>(p, ids);
    break;
  case 5:
    b = blend<5>(p, ids);
    break;
  case 6:
    b = blend<6>(p, ids);
    break;
  case 7:
    b = blend<7>(p, ids);
    break;
  case 8:
    b = blend<8>(p, ids);
    break;
  case 9:
    b = blend<9>(p, ids);
    break;
  case 10:
    b = blend<10>(p, ids);
    break;
  case 11:
    b = blend<11>(p, ids);
    break;
  default:
    b = blend<12>(p, ids);
    break;
  }
  const double weight = b.weight;
  const std::array<double, NoiseOctaves::kOctaves>& octaveAmplitude = b.octaveAmplitude;
  if (weight <= 0.0)
    return {};
  // Wavelengths are powers of two, so multiplying by the (exact) reciprocal is bit-identical
  // to dividing, and much cheaper. The amplitudes are normalised by one reciprocal of the
  // weight rather than a division per octave. The octaves that matter are gathered first and
  // evaluated two at a time (GradientNoise::at2), then summed in octave order.
  const double perWeight = 1.0 / weight;
  std::array<double, NoiseOctaves::kOctaves + 1> xs{}, ys{}, coefficient{}, value{};
  int m = 0;
  double inverse = 1.0 / NoiseOctaves::kLongest;
  for (int k = 0; k < active; ++k, inverse *= 2.0) {
    const double amplitude = octaveAmplitude[static_cast<std::size_t>(k)] * perWeight;
    if (amplitude < 1e-3)
      continue;
    const auto j = static_cast<std::size_t>(m++);
    coefficient[j] = fades.fade[static_cast<std::size_t>(k)] * amplitude;
    xs[j] = p.x * inverse + 37.1 * k;
    ys[j] = p.y * inverse + -11.7 * k;
  }
  for (int j = 0; j < m; j += 2) // an odd count evaluates one padding lane (at 0, 0)
    noise_.at2(xs.data() + j, ys.data() + j, value.data() + j);
  double noise = 0.0;
  for (int j = 0; j < m; ++j)
    noise += coefficient[static_cast<std::size_t>(j)] * value[static_cast<std::size_t>(j)];
  Sample s = blendSums(b.weightedHeight, weight, b.count);
  s.h += noise;
  return s;
}

Sample World::riversAt(Vec2 p, std::span<const std::uint32_t> ids) const noexcept {
  Sample best;
  for (const std::uint32_t i : ids) {
    if (!riverSupport_[i].contains(p))
      continue;
    const primitives::RiverPrimitive& r = data_.rivers[i];
    const CurveHit hit = closestOnCurve(r, riverChunks_[i], p);
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
