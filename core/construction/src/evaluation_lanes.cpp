#include "evaluation_lanes.h"

#include "strahler/base/lanes.h"
#include "strahler/primitives/river_primitive.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

// Kernels pass kLanes-wide vectors between inlined functions; the ABI note does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace strahler::construction {
namespace detail {
namespace {

using base::Doubles;
using base::kLanes;
using base::LaneMask;
using base::splat;

/// Below this amplitude (m) an octave is left out.
constexpr double kNegligibleAmplitude = 1e-3;
/// Coordinates below this magnitude keep every octave's lattice coordinate within
/// LatticeNoise::kLaneLimit (octave offsets add < 500 lattice units).
constexpr double kLaneSafe = noise::LatticeNoise::kLaneLimit - 1000.0;

Doubles load(const double* v) noexcept {
  Doubles d;
  __builtin_memcpy(&d, v, sizeof d);
  return d;
}

void store(double* to, Doubles d) noexcept {
  __builtin_memcpy(to, &d, sizeof d);
}

/// The noise at every lane: atLanes(), or at() per lane where a lane is out of its range.
[[gnu::always_inline]] inline Doubles noiseAt(const noise::LatticeNoise& noise, Doubles x,
                                              Doubles y, bool lanesSafe) noexcept {
  if (lanesSafe)
    return noise.atLanes(x, y);
  Doubles out;
  for (int l = 0; l < kLanes; ++l)
    out[l] = noise.at({x[l], y[l]});
  return out;
}

/// B(T…) at kLanes points: Σ w_i c_i / Σ w_i plus the fBm of the blended amplitude A and gain
/// G, octave k weighted by A (1 − G) / (1 − G^K) · G^k times its LOD fade, octaves below
/// kNegligibleAmplitude left out. Lanes without any covering primitive get {0, 0}.
[[gnu::always_inline]] inline void terrainKernel(const TerrainLaneArgs& a) noexcept {
  const Doubles px = load(a.xs), py = load(a.ys);
  Doubles weight{}, weightedHeight{}, weightedAmplitude{}, weightedRoughness{}, count{};
  const World::HotTerrain* hot = a.hot;
  for (const std::uint32_t i : a.ids) {
    const World::HotTerrain& t = hot[i];
    const Doubles dx = px - t.center.x, dy = py - t.center.y;
    const Doubles d2 = dx * dx + dy * dy;
    const LaneMask inside = d2 < t.radius2;
    const Doubles u = 1.0 - d2 * t.inverseRadius2;
    const Doubles w = inside ? u * u : Doubles{}; // primitives::falloff, by a reciprocal
    weight += w;
    weightedHeight += w * t.elevation;
    weightedAmplitude += w * t.amplitude;
    weightedRoughness += w * t.roughness;
    count += inside ? splat(1.0) : Doubles{};
  }
  const LaneMask covered = weight > 0.0;
  if (!base::anyLane(covered)) {
    store(a.h, Doubles{});
    store(a.w, Doubles{});
    return;
  }
  const Doubles perWeight = 1.0 / weight;
  const Doubles gain = weightedRoughness * perWeight;
  Doubles gainPower = splat(1.0);
  for (int k = 0; k < NoiseOctaves::kOctaves; ++k)
    gainPower *= gain;
  Doubles amplitude = weightedAmplitude * perWeight * (1.0 - gain) / (1.0 - gainPower);
  bool lanesSafe = true;
  for (int l = 0; l < kLanes; ++l)
    lanesSafe = lanesSafe && std::fabs(px[l]) < kLaneSafe && std::fabs(py[l]) < kLaneSafe;
  Doubles noise{};
  double inverse = 1.0 / NoiseOctaves::kLongest; // wavelengths are powers of two: exact
  for (int k = 0; k < a.fades->active; ++k, inverse *= 2.0) {
    const LaneMask present = amplitude >= kNegligibleAmplitude;
    if (!base::anyLane(present))
      break; // amplitudes only decrease (0 ≤ G < 1): every later octave is negligible too
    const Doubles coefficient = a.fades->fade[static_cast<std::size_t>(k)] * amplitude;
    const Doubles value =
        noiseAt(*a.noise, px * inverse + 37.1 * k, py * inverse + -11.7 * k, lanesSafe);
    noise = present ? noise + coefficient * value : noise;
    amplitude *= gain;
  }
  store(a.h, covered ? weightedHeight / weight + noise : Doubles{});
  store(a.w, covered ? weight / count : Doubles{});
}

/// Square root of every lane (IEEE-exact; the file is built without errno so that this
/// loop becomes one vector instruction).
[[gnu::always_inline]] inline Doubles sqrtLanes(Doubles v) noexcept {
  for (int l = 0; l < kLanes; ++l)
    v[l] = __builtin_sqrt(v[l]);
  return v;
}

/// Squared distance from each lane to the box [lo, hi] (0 inside).
[[gnu::always_inline]] inline Doubles boxDistance2(Doubles px, Doubles py, double loX, double loY,
                                                   double hiX, double hiY) noexcept {
  Doubles dx = loX - px, dy = loY - py;
  const Doubles zero{};
  dx = dx > zero ? dx : zero;
  dy = dy > zero ? dy : zero;
  const Doubles ex = px - hiX, ey = py - hiY;
  dx = ex > dx ? ex : dx;
  dy = ey > dy ? ey : dy;
  return dx * dx + dy * dy;
}

/// The closest point of a river curve per lane: segments whose box, or whose run's box, is no
/// closer than the best hit so far are skipped (per lane, as one point alone would skip them),
/// and the search starts bounded by the river's radius (w = 0 beyond).
[[gnu::always_inline]] inline void curveKernel(const CurveLaneArgs& a) noexcept {
  const Doubles px = load(a.xs), py = load(a.ys);
  LaneMask active;
  __builtin_memcpy(&active, a.active, sizeof active);
  const primitives::RiverPrimitive& r = *a.river;
  Doubles bound2 = splat(r.radius * r.radius);
  Doubles bestDistance = splat(std::numeric_limits<double>::infinity());
  Doubles bestElevation{}, bestAlong{};
  const std::size_t n = r.curve.size();
  const double last = static_cast<double>(n - 1);
  LaneMask inRun{};
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (k % kChunk == 0) {
      const geometry::Aabb& c = a.chunks[k / kChunk];
      inRun = active & (boxDistance2(px, py, c.min.x, c.min.y, c.max.x, c.max.y) < bound2);
      if (!base::anyLane(inRun)) {
        k += kChunk - 1;
        continue;
      }
    }
    const primitives::CurvePoint& pa = r.curve[k];
    const primitives::CurvePoint& pb = r.curve[k + 1];
    const geometry::Vec2 sa = pa.position, sb = pb.position;
    const LaneMask nearBox =
        inRun & (boxDistance2(px, py, std::min(sa.x, sb.x), std::min(sa.y, sb.y),
                              std::max(sa.x, sb.x), std::max(sa.y, sb.y)) < bound2);
    if (!base::anyLane(nearBox))
      continue;
    // geometry::closestPointOnSegment, lane by lane.
    const geometry::Vec2 ab = sb - sa;
    const double len2 = lengthSquared(ab);
    Doubles qx = splat(sa.x), qy = splat(sa.y);
    if (len2 != 0.0) {
      Doubles t = ((px - sa.x) * ab.x + (py - sa.y) * ab.y) / len2;
      const Doubles zero{}, one = splat(1.0);
      t = t < zero ? zero : t;
      t = one < t ? one : t;
      qx = sa.x + ab.x * t;
      qy = sa.y + ab.y * t;
    }
    const Doubles ex = px - qx, ey = py - qy;
    const Doubles d2 = ex * ex + ey * ey;
    const LaneMask closer = nearBox & (d2 < bound2);
    if (!base::anyLane(closer))
      continue;
    bound2 = closer ? d2 : bound2;
    const double span = distance(sa, sb);
    Doubles along{};
    if (span > 0.0) {
      const Doubles fx = sa.x - qx, fy = sa.y - qy;
      along = sqrtLanes(fx * fx + fy * fy) / span;
    }
    bestDistance = closer ? sqrtLanes(d2) : bestDistance;
    bestElevation = closer ? pa.elevation + (pb.elevation - pa.elevation) * along : bestElevation;
    bestAlong = closer ? (static_cast<double>(k) + along) / last : bestAlong;
  }
  store(a.distance, bestDistance);
  store(a.elevation, bestElevation);
  store(a.along, bestAlong);
}

/// A kernel compiled for one instruction set: the baseline (SSE2), AVX2 and AVX-512F.
template <class Args, void (*kKernel)(const Args&) noexcept> struct Compiled {
  static void baseline(const Args& a) noexcept { kKernel(a); }
  __attribute__((target("avx2"))) static void avx2(const Args& a) noexcept { kKernel(a); }
  __attribute__((target("avx512f"))) static void avx512(const Args& a) noexcept { kKernel(a); }
};

bool supported(InstructionSet set) noexcept {
  switch (set) {
  case InstructionSet::kAvx512:
    return __builtin_cpu_supports("avx512f");
  case InstructionSet::kAvx2:
    return __builtin_cpu_supports("avx2");
  case InstructionSet::kBaseline:
    return true;
  }
  return false;
}

InstructionSet widest() noexcept {
  for (InstructionSet set : {InstructionSet::kAvx512, InstructionSet::kAvx2})
    if (supported(set))
      return set;
  return InstructionSet::kBaseline;
}

std::atomic<InstructionSet>& current() noexcept {
  static std::atomic<InstructionSet> set{widest()};
  return set;
}

} // namespace

/// Runs the build of `kKernel` for the instruction set in use.
template <class Args, void (*kKernel)(const Args&) noexcept>
void runCompiled(const Args& args) noexcept {
  using Builds = Compiled<Args, kKernel>;
  switch (current().load(std::memory_order_relaxed)) {
  case InstructionSet::kAvx512:
    return Builds::avx512(args);
  case InstructionSet::kAvx2:
    return Builds::avx2(args);
  case InstructionSet::kBaseline:
    break;
  }
  Builds::baseline(args);
}

void closestOnCurveLanes(const CurveLaneArgs& args) noexcept {
  runCompiled<CurveLaneArgs, curveKernel>(args);
}

void terrainLanes(const TerrainLaneArgs& args) noexcept {
  runCompiled<TerrainLaneArgs, terrainKernel>(args);
}

} // namespace detail

InstructionSet instructionSet() noexcept {
  return detail::current().load(std::memory_order_relaxed);
}

bool useInstructionSet(InstructionSet set) noexcept {
  if (!detail::supported(set))
    return false;
  detail::current().store(set, std::memory_order_relaxed);
  return true;
}

} // namespace strahler::construction
