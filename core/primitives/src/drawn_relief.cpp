#include "strahler/primitives/drawn_relief.h"

#include "strahler/base/smoothstep.h"
#include "strahler/geometry/distance.h"
#include "strahler/network/relief_law.h"
#include "strahler/primitives/quantization.h"
#include "strahler/primitives/river_primitives.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace strahler::primitives {
namespace {

using geometry::Vec2;

/// Arc length between the crest's height samples, m.
constexpr double kCrestStep = 100.0;
/// Half-window of the running max and mean that make the law's crest continuous, in samples.
constexpr std::ptrdiff_t kCrestSmoothing = 10;
/// Share of the noise amplitude taken off on a crest, and the distance over which it returns.
constexpr double kCrestCalm = 0.7;
constexpr double kCrestCalmReach = 1000.0;
/// Share of a hillslope's gradient a primitive's plane keeps (terrain_primitives.cpp).
constexpr double kPlaneShare = 0.25;
/// Steepest plane a scaled primitive keeps (terrain_primitives.cpp: tan 40° × plane share).
constexpr double kMaxPlane = 0.84 * kPlaneShare;

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

void liftCrests(const input::WorldSpec& spec, std::vector<TerrainPrimitive>& terrain,
                std::span<const TerrainBase> bases) {
  if (spec.features.ridges.empty())
    return;
  const double area = geometry::area(spec.land);
  for (const input::RidgeFeature& ridge : spec.features.ridges) {
    const std::vector<Vec2>& line = ridge.line;
    const double halfWidth = network::ridgeHalfWidth(ridge, area);
    std::vector<double> along{0.0};
    geometry::Aabb box;
    for (std::size_t k = 0; k < line.size(); ++k) {
      box.add(line[k]);
      if (k > 0)
        along.push_back(along.back() + distance(line[k - 1], line[k]));
    }
    box = box.expanded(halfWidth);
    // The primitives within the half-width, and the highest e + flank d near each sample.
    std::vector<std::pair<std::size_t, AlongHit>> near;
    for (std::size_t i = 0; i < terrain.size(); ++i)
      if (box.contains(terrain[i].center))
        if (const AlongHit hit = nearestAlong(line, along, terrain[i].center);
            hit.distance < halfWidth)
          near.emplace_back(i, hit);
    const auto samples = static_cast<std::size_t>(std::floor(along.back() / kCrestStep)) + 2;
    std::vector<double> raw(samples,
                            ridge.elevation.value_or(-std::numeric_limits<double>::infinity()));
    // The crest rises above its flanks by kCrestFlank per metre, but no more than kCrestRise
    // above the highest primitive near it (or to the ridge's own elevation): beside a drawn
    // summit off the line, the flank rule alone put the crest hundreds of metres above the
    // summit (Corsica: a 3,263 m peak beside Rotondo's 2,622 m).
    std::vector<double> highest(samples, -std::numeric_limits<double>::infinity());
    for (const auto& [i, hit] : near)
      if (hit.distance <= kCrestReach) {
        const auto k = std::min(static_cast<std::size_t>(hit.along / kCrestStep), samples - 2);
        const double top = terrain[i].elevation + kCrestFlank * hit.distance;
        raw[k] = std::max(raw[k], top);
        raw[k + 1] = std::max(raw[k + 1], top);
        highest[k] = std::max(highest[k], terrain[i].elevation);
        highest[k + 1] = std::max(highest[k + 1], terrain[i].elevation);
      }
    for (std::size_t k = 0; k < samples; ++k)
      if (std::isfinite(highest[k]))
        raw[k] = std::min(raw[k], std::max(highest[k] + kCrestRise,
                                           ridge.elevation.value_or(highest[k] + kCrestRise)));
    // Samples with nothing near take the nearest sample's height (0 when none has one).
    double last = -std::numeric_limits<double>::infinity();
    for (double& z : raw)
      z = std::isfinite(z) ? (last = z) : last;
    last = -std::numeric_limits<double>::infinity();
    for (auto it = raw.rbegin(); it != raw.rend(); ++it)
      *it = std::isfinite(*it) ? (last = *it) : last;
    for (double& z : raw)
      z = std::isfinite(z) ? z : 0.0;
    const std::vector<double> crest = smoothCrest(raw);
    for (const auto& [i, hit] : near) {
      TerrainPrimitive& t = terrain[i];
      const double s = hit.along / kCrestStep;
      const auto k = std::min(static_cast<std::size_t>(s), samples - 2);
      const double f = std::clamp(s - static_cast<double>(k), 0.0, 1.0);
      const double tent = crest[k] + (crest[k + 1] - crest[k]) * f - kCrestFlank * hit.distance;
      const double clear = base::smoothstep(bases[i].distance / kCrestRiverClearance);
      const double hold = clear * base::smoothstep(2.0 * (1.0 - hit.distance / halfWidth));
      if (tent > t.elevation && hold > 0.0) {
        const Vec2 down = hit.distance > 1.0
                              ? (t.center - hit.point) * (-kCrestFlank * kPlaneShare / hit.distance)
                              : Vec2{};
        const Vec2 slope = t.slope * (1.0 - hold) + down * hold;
        t.elevation = quantize(t.elevation + (tent - t.elevation) * hold, Quantum::kElevation);
        t.slope = {quantize(slope.x, Quantum::kSlope), quantize(slope.y, Quantum::kSlope)};
      }
      const double calm =
          1.0 - kCrestCalm * clear * base::smoothstep(1.0 - hit.distance / kCrestCalmReach);
      t.amplitude = quantize(t.amplitude * calm, Quantum::kElevation);
    }
  }
}

void keepValleysOffCrests(const input::WorldSpec& spec, std::vector<RiverPrimitive>& rivers) {
  for (const input::RidgeFeature& ridge : spec.features.ridges) {
    geometry::Aabb box;
    for (Vec2 p : ridge.line)
      box.add(p);
    for (RiverPrimitive& r : rivers) {
      if (!supportBox(r).intersects(box.expanded(kValleyCrestMargin)))
        continue;
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k + 1 < r.curve.size(); ++k)
        for (std::size_t j = 0; j + 1 < ridge.line.size(); ++j) {
          // The nearest points of two segments: one of the four ends is in every pair.
          const Vec2 a = r.curve[k].position, b = r.curve[k + 1].position;
          const Vec2 c = ridge.line[j], d = ridge.line[j + 1];
          nearest = std::min({nearest, distance(a, geometry::closestPointOnSegment(a, c, d)),
                              distance(b, geometry::closestPointOnSegment(b, c, d)),
                              distance(c, geometry::closestPointOnSegment(c, a, b)),
                              distance(d, geometry::closestPointOnSegment(d, a, b))});
        }
      const double reach = nearest - kValleyCrestMargin;
      if (reach < r.radius)
        r.radius = std::max(quantize(std::max(reach, 0.0), Quantum::kRadius),
                            std::min(r.radius, valleyMinReach(r.type, r.widthUp, r.widthDown)));
    }
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
  // The strongest raise and the strongest lowering, not their sums: where two mountains'
  // reaches overlap the relief between them is not raised twice (summed, Corsica's Rotondo
  // and d'Oro made a 3,232 m peak between them, higher than either was drawn).
  double raise = 0.0, lower = 0.0;
  for (std::size_t m = 0; m < gains.size(); ++m) {
    const double excess =
        (gains[m] - 1.0) *
        base::smoothstep(1.0 - distance(p, features.mountains[m].position) / radii[m]);
    raise = std::max(raise, excess);
    lower = std::min(lower, excess);
  }
  return std::max(1.0 + raise + lower, 0.0);
}

std::optional<double> mountainCap(const input::Features& features, std::span<const double> radii,
                                  Vec2 p) noexcept {
  std::optional<double> cap;
  for (std::size_t m = 0; m < radii.size(); ++m) {
    const input::MountainFeature& mountain = features.mountains[m];
    const double d = distance(p, mountain.position);
    if (mountain.elevation && d < radii[m])
      cap = std::max(cap.value_or(-std::numeric_limits<double>::infinity()),
                     *mountain.elevation - kSummitFall * d);
  }
  return cap;
}

TerrainPrimitive scaleRelief(const TerrainPrimitive& t, double base, double gain,
                             std::optional<double> cap) noexcept {
  TerrainPrimitive out = t;
  if (t.elevation > base) {
    double e = base + gain * (t.elevation - base);
    if (cap && e > t.elevation)
      e = std::max(t.elevation, std::min(e, *cap)); // raised no higher than the summit's cone
    out.elevation = quantize(e, Quantum::kElevation);
  }
  Vec2 slope = t.slope * gain;
  if (const double steepness = length(slope); steepness > kMaxPlane)
    slope = slope * (kMaxPlane / steepness);
  out.slope = {quantize(slope.x, Quantum::kSlope), quantize(slope.y, Quantum::kSlope)};
  out.amplitude = quantize(t.amplitude * gain, Quantum::kElevation);
  return out;
}

} // namespace strahler::primitives
