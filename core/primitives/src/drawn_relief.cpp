#include "strahler/primitives/drawn_relief.h"

#include "strahler/geometry/distance.h"
#include "strahler/primitives/quantization.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strahler::primitives {
namespace {

using geometry::Vec2;

/// Arc length between the crest's height samples, m.
constexpr double kCrestStep = 100.0;
/// How far from a crest sample the analysis' ridge elevations count (the law's crest), m.
constexpr double kCrestSearch = 1500.0;
/// Half-window of the running max and mean that make the law's crest continuous, in samples.
constexpr std::ptrdiff_t kCrestSmoothing = 10;
/// Share of the noise amplitude taken off on a crest, and the distance over which it returns.
constexpr double kCrestCalm = 0.7;
constexpr double kCrestCalmReach = 1000.0;
/// Steepest plane a scaled primitive keeps (terrain_primitives.cpp: tan 40° × plane share).
constexpr double kMaxPlane = 0.84 * 0.25;

double smoothstep(double t) noexcept {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

/// Nearest point of a polyline with the arc length there.
struct AlongHit {
  double distance = std::numeric_limits<double>::infinity();
  Vec2 point;
  double along = 0.0;
};

AlongHit nearestAlong(const std::vector<Vec2>& line, const std::vector<double>& along, Vec2 p) {
  AlongHit best;
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const Vec2 q = geometry::closestPointOnSegment(p, line[k], line[k + 1]);
    if (const double d = distance(p, q); d < best.distance)
      best = {d, q, along[k] + distance(line[k], q)};
  }
  return best;
}

/// Running max then running mean over ±kCrestSmoothing samples.
std::vector<double> smoothCrest(const std::vector<double>& raw) {
  const auto n = static_cast<std::ptrdiff_t>(raw.size());
  std::vector<double> highest(raw.size()), out(raw.size());
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    double h = raw[static_cast<std::size_t>(k)];
    for (std::ptrdiff_t j = std::max<std::ptrdiff_t>(0, k - kCrestSmoothing);
         j <= std::min(n - 1, k + kCrestSmoothing); ++j)
      h = std::max(h, raw[static_cast<std::size_t>(j)]);
    highest[static_cast<std::size_t>(k)] = h;
  }
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    double sum = 0.0, count = 0.0;
    for (std::ptrdiff_t j = std::max<std::ptrdiff_t>(0, k - kCrestSmoothing);
         j <= std::min(n - 1, k + kCrestSmoothing); ++j) {
      sum += highest[static_cast<std::size_t>(j)];
      count += 1.0;
    }
    out[static_cast<std::size_t>(k)] = sum / count;
  }
  return out;
}

} // namespace

DrawnRidges::DrawnRidges(const input::WorldSpec& spec, const analysis::Hydrology& hydrology,
                         const network::ReliefLaw& law) {
  for (const input::RidgeFeature& ridge : spec.features.ridges) {
    Crest c;
    c.line = ridge.line;
    c.halfWidth = network::ridgeHalfWidth(ridge, law.landAreaM2());
    c.along.push_back(0.0);
    for (std::size_t k = 1; k < c.line.size(); ++k)
      c.along.push_back(c.along.back() + distance(c.line[k - 1], c.line[k]));
    const auto samples = static_cast<std::size_t>(std::floor(c.along.back() / kCrestStep)) + 2;
    if (ridge.elevation) {
      c.height.assign(samples, *ridge.elevation);
    } else {
      // The analysis' ridge elevations near the line, then the highest near each sample.
      std::vector<std::pair<AlongHit, double>> near;
      const blocks::BlockSet& blocks = hydrology.blocks;
      for (std::size_t v = 0; v < blocks.vertices.size(); ++v) {
        const AlongHit hit = nearestAlong(c.line, c.along, blocks.vertices[v].position);
        if (hit.distance <= kCrestSearch)
          near.emplace_back(hit, hydrology.analysis.ridgeElevation[v]);
      }
      std::vector<double> raw(samples, -std::numeric_limits<double>::infinity());
      for (const auto& [hit, z] : near) {
        // Samples within kCrestSearch of the vertex along the line (a bound: |Δs| ≤ search).
        const double reach = std::sqrt(kCrestSearch * kCrestSearch - hit.distance * hit.distance);
        const auto k0 =
            static_cast<std::size_t>(std::max(0.0, std::ceil((hit.along - reach) / kCrestStep)));
        for (std::size_t k = k0;
             k < samples && static_cast<double>(k) * kCrestStep <= hit.along + reach; ++k)
          raw[k] = std::max(raw[k], z);
      }
      // Samples with no vertex near take the nearest sample's height (0 when none has one).
      double last = -std::numeric_limits<double>::infinity();
      for (double& z : raw)
        z = std::isfinite(z) ? (last = z) : last;
      last = -std::numeric_limits<double>::infinity();
      for (auto it = raw.rbegin(); it != raw.rend(); ++it)
        *it = std::isfinite(*it) ? (last = *it) : last;
      for (double& z : raw)
        z = std::isfinite(z) ? z : 0.0;
      c.height = smoothCrest(raw);
    }
    crests_.push_back(std::move(c));
  }
}

double DrawnRidges::crestAt(std::size_t i, Vec2 p) const noexcept {
  const Crest& c = crests_[i];
  const double s = nearestAlong(c.line, c.along, p).along / kCrestStep;
  const auto k = std::min(static_cast<std::size_t>(s), c.height.size() - 2);
  const double t = std::clamp(s - static_cast<double>(k), 0.0, 1.0);
  return c.height[k] + (c.height[k + 1] - c.height[k]) * t;
}

void DrawnRidges::lift(Vec2 c, double riverDistance, double& elevation, Vec2& slope,
                       double& amplitude) const noexcept {
  const double clear = smoothstep(riverDistance / kCrestRiverClearance);
  for (std::size_t i = 0; i < crests_.size(); ++i) {
    const Crest& crest = crests_[i];
    const AlongHit hit = nearestAlong(crest.line, crest.along, c);
    if (hit.distance >= crest.halfWidth)
      continue;
    const double hold = clear * smoothstep(2.0 * (1.0 - hit.distance / crest.halfWidth));
    const double tent = crestAt(i, c) - kCrestFlank * hit.distance;
    if (tent > elevation) {
      const Vec2 down =
          hit.distance > 1.0 ? (c - hit.point) * (-kCrestFlank / hit.distance) : Vec2{};
      elevation += (tent - elevation) * hold;
      slope = slope * (1.0 - hold) + down * hold;
    }
    amplitude *= 1.0 - kCrestCalm * clear * smoothstep(1.0 - hit.distance / kCrestCalmReach);
  }
}

std::vector<double> mountainRadii(const input::WorldSpec& spec) {
  std::vector<double> radii;
  if (spec.features.mountains.empty())
    return radii;
  const double area = geometry::area(spec.land);
  for (const input::MountainFeature& m : spec.features.mountains)
    radii.push_back(network::mountainRadius(m, area));
  return radii;
}

double mountainGain(const input::Features& features, std::span<const double> radii,
                    std::span<const double> gains, Vec2 p) noexcept {
  double gain = 1.0;
  for (std::size_t m = 0; m < gains.size(); ++m)
    gain +=
        (gains[m] - 1.0) * smoothstep(1.0 - distance(p, features.mountains[m].position) / radii[m]);
  return std::max(gain, 0.0);
}

TerrainPrimitive scaleRelief(const TerrainPrimitive& t, double base, double gain) noexcept {
  TerrainPrimitive out = t;
  if (t.elevation > base)
    out.elevation = quantize(base + gain * (t.elevation - base), Quantum::kElevation);
  Vec2 slope = t.slope * gain;
  if (const double steepness = length(slope); steepness > kMaxPlane)
    slope = slope * (kMaxPlane / steepness);
  out.slope = {quantize(slope.x, Quantum::kSlope), quantize(slope.y, Quantum::kSlope)};
  out.amplitude = quantize(t.amplitude * gain, Quantum::kElevation);
  return out;
}

} // namespace strahler::primitives
