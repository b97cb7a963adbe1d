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

/// Below this amplitude (m) an octave is left out.
constexpr double kNegligibleAmplitude = 1e-3;
/// Coordinates below this magnitude keep every octave's lattice coordinate within
/// LatticeNoise::kLaneLimit (octave offsets add < 500 lattice units).
constexpr double kLaneSafe = noise::LatticeNoise::kLaneLimit - 1000.0;

/// Eight samples per pass, in vector registers (tiles, rasters).
struct Wide {
  using D = Doubles;
  using M = LaneMask;
  [[gnu::always_inline]] static D load(const double* v) noexcept {
    D d;
    __builtin_memcpy(&d, v, sizeof d);
    return d;
  }
  [[gnu::always_inline]] static M loadMask(const std::int64_t* v) noexcept {
    M m;
    __builtin_memcpy(&m, v, sizeof m);
    return m;
  }
  [[gnu::always_inline]] static void store(double* to, D d) noexcept {
    __builtin_memcpy(to, &d, sizeof d);
  }
  [[gnu::always_inline]] static D splat(double v) noexcept { return base::splat(v); }
  [[gnu::always_inline]] static bool any(M m) noexcept { return base::anyLane(m); }
  [[gnu::always_inline]] static M both(M a, M b) noexcept { return a & b; }
  /// IEEE-exact; the file is built without errno so that this loop is one instruction.
  [[gnu::always_inline]] static D sqrt(D v) noexcept {
    for (int l = 0; l < kLanes; ++l)
      v[l] = __builtin_sqrt(v[l]);
    return v;
  }
  /// The box of the points (x[l], y[l]).
  [[gnu::always_inline]] static geometry::Aabb bounds(D x, D y) noexcept {
    geometry::Aabb box;
    for (int l = 0; l < kLanes; ++l)
      box.add(geometry::Vec2{x[l], y[l]});
    return box;
  }
  [[gnu::always_inline]] static bool allBelow(D x, D y, double limit) noexcept {
    bool below = true;
    for (int l = 0; l < kLanes; ++l)
      below = below && std::fabs(x[l]) < limit && std::fabs(y[l]) < limit;
    return below;
  }
  /// atLanes(), or at() lane by lane unless every lane is `safe` for atLanes().
  [[gnu::always_inline]] static D noise(const noise::LatticeNoise& n, D x, D y,
                                        bool safe) noexcept {
    if (safe)
      return n.atLanes(x, y);
    D out;
    for (int l = 0; l < kLanes; ++l)
      out[l] = n.at({x[l], y[l]});
    return out;
  }
};

/// One sample in scalar registers (single points): the operations of one lane of Wide.
struct Single {
  using D = double;
  using M = bool;
  [[gnu::always_inline]] static D load(const double* v) noexcept { return *v; }
  [[gnu::always_inline]] static M loadMask(const std::int64_t* v) noexcept { return *v != 0; }
  [[gnu::always_inline]] static void store(double* to, D d) noexcept { *to = d; }
  [[gnu::always_inline]] static D splat(double v) noexcept { return v; }
  [[gnu::always_inline]] static bool any(M m) noexcept { return m; }
  [[gnu::always_inline]] static M both(M a, M b) noexcept { return a && b; }
  [[gnu::always_inline]] static D sqrt(D v) noexcept { return __builtin_sqrt(v); }
  [[gnu::always_inline]] static geometry::Aabb bounds(D x, D y) noexcept {
    return {{x, y}, {x, y}};
  }
  [[gnu::always_inline]] static bool allBelow(D x, D y, double limit) noexcept {
    return std::fabs(x) < limit && std::fabs(y) < limit;
  }
  [[gnu::always_inline]] static D noise(const noise::LatticeNoise& n, D x, D y, bool) noexcept {
    return n.at({x, y});
  }
};

/// The weighted sums of the terrain blend at the points of L (Wide or Single): Σ w_i,
/// Σ w_i c_i, Σ w_i A_i, Σ w_i G_i and the number of covering primitives, into a.sums.
template <class L>
[[gnu::always_inline]] inline void terrainSumsKernel(const TerrainLaneArgs& a) noexcept {
  using D = typename L::D;
  using M = typename L::M;
  const D px = L::load(a.xs), py = L::load(a.ys);
  D weight{}, weightedHeight{}, weightedAmplitude{}, weightedRoughness{}, count{};
  const World::HotTerrain* hot = a.hot;
  for (const std::uint32_t i : a.ids) {
    const World::HotTerrain& t = hot[i];
    const D dx = px - t.center.x, dy = py - t.center.y;
    const D d2 = dx * dx + dy * dy;
    const M inside = d2 < t.radius2;
    const D u = 1.0 - d2 * t.inverseRadius2;
    const D w = inside ? u * u : D{}; // primitives::falloff, by a reciprocal
    weight += w;
    weightedHeight += w * t.elevation;
    weightedAmplitude += w * t.amplitude;
    weightedRoughness += w * t.roughness;
    count += inside ? L::splat(1.0) : D{};
  }
  L::store(a.sums->weight, weight);
  L::store(a.sums->height, weightedHeight);
  L::store(a.sums->amplitude, weightedAmplitude);
  L::store(a.sums->roughness, weightedRoughness);
  L::store(a.sums->count, count);
}

/// B(T…) at the points of L from their sums (terrainSumsKernel): Σ w_i c_i / Σ w_i plus the
/// fBm of the blended amplitude A and gain G, octave k weighted by A (1 − G) / (1 − G^K) · G^k
/// times its LOD fade, octaves below kNegligibleAmplitude left out. Points without any
/// covering primitive get {0, 0}.
template <class L>
[[gnu::always_inline]] inline void terrainNoiseKernel(const TerrainLaneArgs& a) noexcept {
  using D = typename L::D;
  using M = typename L::M;
  const D weight = L::load(a.sums->weight);
  const M covered = weight > 0.0;
  if (!L::any(covered)) {
    L::store(a.h, D{});
    L::store(a.w, D{});
    return;
  }
  const D px = L::load(a.xs), py = L::load(a.ys);
  const D perWeight = 1.0 / weight;
  const D gain = L::load(a.sums->roughness) * perWeight;
  D gainPower = L::splat(1.0);
  for (int k = 0; k < NoiseOctaves::kOctaves; ++k)
    gainPower *= gain;
  D amplitude = L::load(a.sums->amplitude) * perWeight * (1.0 - gain) / (1.0 - gainPower);
  const bool lanesSafe = L::allBelow(px, py, kLaneSafe);
  D noise{};
  double inverse = 1.0 / NoiseOctaves::kLongest; // wavelengths are powers of two: exact
  for (int k = 0; k < a.fades->active; ++k, inverse *= 2.0) {
    const M present = amplitude >= kNegligibleAmplitude;
    if (!L::any(present))
      break; // amplitudes only decrease (0 ≤ G < 1): every later octave is negligible too
    const D coefficient = a.fades->fade[static_cast<std::size_t>(k)] * amplitude;
    const D value =
        L::noise(*a.noise, px * inverse + 37.1 * k, py * inverse + -11.7 * k, lanesSafe);
    noise = present ? noise + coefficient * value : noise;
    amplitude *= gain;
  }
  L::store(a.h, covered ? L::load(a.sums->height) / weight + noise : D{});
  L::store(a.w, covered ? weight / L::load(a.sums->count) : D{});
}

/// Both phases at one point, in scalar registers.
template <class L>
[[gnu::always_inline]] inline void terrainKernel(const TerrainLaneArgs& a) noexcept {
  terrainSumsKernel<L>(a);
  terrainNoiseKernel<L>(a);
}

/// Squared distance from each point to the box [lo, hi] (0 inside).
template <class D>
[[gnu::always_inline]] inline D boxDistance2(D px, D py, double loX, double loY, double hiX,
                                             double hiY) noexcept {
  D dx = loX - px, dy = loY - py;
  const D zero{};
  dx = dx > zero ? dx : zero;
  dy = dy > zero ? dy : zero;
  const D ex = px - hiX, ey = py - hiY;
  dx = ex > dx ? ex : dx;
  dy = ey > dy ? ey : dy;
  return dx * dx + dy * dy;
}

/// Squared gap between boxes a and [lo, hi], never more than boxDistance2() from any point of
/// a to [lo, hi] (rounding is monotone): a gap ≥ a bound rules out every point of a at once.
[[gnu::always_inline]] inline double boxGap2(const geometry::Aabb& a, double loX, double loY,
                                             double hiX, double hiY) noexcept {
  const double dx = std::max({loX - a.max.x, 0.0, a.min.x - hiX});
  const double dy = std::max({loY - a.max.y, 0.0, a.min.y - hiY});
  return dx * dx + dy * dy;
}

/// The closest point of a river curve to each point of L inside the river's support box,
/// over the runs [firstChunk, chunks.size()): segments whose box, or whose run's box, is no
/// closer than the best hit so far are skipped (per lane, as one point alone would skip them),
/// and the search starts bounded by the river's radius (w = 0 beyond). Returns whether any
/// point found a segment within the radius.
template <class L> [[gnu::always_inline]] inline bool curveKernel(const CurveLaneArgs& a) noexcept {
  using D = typename L::D;
  using M = typename L::M;
  const D px = L::load(a.xs), py = L::load(a.ys);
  const geometry::Aabb& s = a.support;
  const M active =
      L::both(L::both(px >= s.min.x, px <= s.max.x), L::both(py >= s.min.y, py <= s.max.y));
  const primitives::RiverPrimitive& r = *a.river;
  D bound2 = L::splat(r.radius * r.radius);
  D bestDistance = L::splat(std::numeric_limits<double>::infinity());
  D bestElevation{}, bestAlong{};
  if (!L::any(active)) {
    L::store(a.distance, bestDistance);
    return false;
  }
  const std::size_t n = std::min(r.curve.size(), a.chunks.size() * kChunk + 1);
  const double last = static_cast<double>(r.curve.size() - 1);
  // Runs and segments out of the radius of the points' box are skipped in scalar code first.
  const geometry::Aabb points = L::bounds(px, py);
  const double radius2 = r.radius * r.radius;
  M inRun{}, found{};
  for (std::size_t k = a.firstChunk * kChunk; k + 1 < n; ++k) {
    if (k % kChunk == 0) {
      const geometry::Aabb& c = a.chunks[k / kChunk];
      if (boxGap2(points, c.min.x, c.min.y, c.max.x, c.max.y) >= radius2) {
        k += kChunk - 1;
        continue;
      }
      inRun = L::both(active, boxDistance2(px, py, c.min.x, c.min.y, c.max.x, c.max.y) < bound2);
      if (!L::any(inRun)) {
        k += kChunk - 1;
        continue;
      }
    }
    const primitives::CurvePoint& pa = r.curve[k];
    const primitives::CurvePoint& pb = r.curve[k + 1];
    const geometry::Vec2 sa = pa.position, sb = pb.position;
    const double loX = std::min(sa.x, sb.x), loY = std::min(sa.y, sb.y);
    const double hiX = std::max(sa.x, sb.x), hiY = std::max(sa.y, sb.y);
    if (boxGap2(points, loX, loY, hiX, hiY) >= radius2)
      continue;
    const M nearBox = L::both(inRun, boxDistance2(px, py, loX, loY, hiX, hiY) < bound2);
    if (!L::any(nearBox))
      continue;
    // geometry::closestPointOnSegment, lane by lane.
    const geometry::Vec2 ab = sb - sa;
    const double len2 = lengthSquared(ab);
    D qx = L::splat(sa.x), qy = L::splat(sa.y);
    if (len2 != 0.0) {
      D t = ((px - sa.x) * ab.x + (py - sa.y) * ab.y) / len2;
      const D zero{}, one = L::splat(1.0);
      t = t < zero ? zero : t;
      t = one < t ? one : t;
      qx = sa.x + ab.x * t;
      qy = sa.y + ab.y * t;
    }
    const D ex = px - qx, ey = py - qy;
    const D d2 = ex * ex + ey * ey;
    const M closer = L::both(nearBox, d2 < bound2);
    if (!L::any(closer))
      continue;
    bound2 = closer ? d2 : bound2;
    found = found | closer;
    const double span = distance(sa, sb);
    D along{};
    if (span > 0.0) {
      const D fx = sa.x - qx, fy = sa.y - qy;
      along = L::sqrt(fx * fx + fy * fy) / span;
    }
    bestDistance = closer ? L::sqrt(d2) : bestDistance;
    bestElevation = closer ? pa.elevation + (pb.elevation - pa.elevation) * along : bestElevation;
    bestAlong = closer ? (static_cast<double>(k) + along) / last : bestAlong;
  }
  L::store(a.distance, bestDistance);
  L::store(a.elevation, bestElevation);
  L::store(a.along, bestAlong);
  return L::any(found);
}

/// The squared distance from each point of L to the nearest of a.ids (see SegmentLaneArgs).
template <class L>
[[gnu::always_inline]] inline void nearestSegmentKernel(const SegmentLaneArgs& a) noexcept {
  using D = typename L::D;
  const D px = L::load(a.xs), py = L::load(a.ys);
  D best2 = L::load(a.best2);
  for (const std::uint32_t i : a.ids) {
    const geometry::Vec2 sa = a.segments[i].a, sb = a.segments[i].b;
    // geometry::closestPointOnSegment, lane by lane.
    const geometry::Vec2 ab = sb - sa;
    const double len2 = lengthSquared(ab);
    D qx = L::splat(sa.x), qy = L::splat(sa.y);
    if (len2 != 0.0) {
      D t = ((px - sa.x) * ab.x + (py - sa.y) * ab.y) / len2;
      const D zero{}, one = L::splat(1.0);
      t = t < zero ? zero : t;
      t = one < t ? one : t;
      qx = sa.x + ab.x * t;
      qy = sa.y + ab.y * t;
    }
    const D ex = qx - px, ey = qy - py;
    const D d2 = ex * ex + ey * ey;
    best2 = d2 < best2 ? d2 : best2;
  }
  L::store(a.best2, best2);
}

/// A kernel compiled for one instruction set: the baseline (SSE2), AVX2 and AVX-512F.
template <class R, class Args, R (*kKernel)(const Args&) noexcept> struct Compiled {
  static R baseline(const Args& a) noexcept { return kKernel(a); }
  __attribute__((target("avx2"))) static R avx2(const Args& a) noexcept { return kKernel(a); }
  __attribute__((target("avx512f"))) static R avx512(const Args& a) noexcept { return kKernel(a); }
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
template <class R, class Args, R (*kKernel)(const Args&) noexcept>
R runCompiled(const Args& args) noexcept {
  using Builds = Compiled<R, Args, kKernel>;
  switch (current().load(std::memory_order_relaxed)) {
  case InstructionSet::kAvx512:
    return Builds::avx512(args);
  case InstructionSet::kAvx2:
    return Builds::avx2(args);
  case InstructionSet::kBaseline:
    break;
  }
  return Builds::baseline(args);
}

bool closestOnCurveLanes(const CurveLaneArgs& args) noexcept {
  return runCompiled<bool, CurveLaneArgs, curveKernel<Wide>>(args);
}

bool closestOnCurvePoint(const CurveLaneArgs& args) noexcept {
  return curveKernel<Single>(args);
}

void terrainLanes(const TerrainLaneArgs& args) noexcept {
  // Two builds, not one: in a single function GCC keeps the sums' accumulators on the stack
  // (the noise needs many registers), and every candidate then waits on a store.
  runCompiled<void, TerrainLaneArgs, terrainSumsKernel<Wide>>(args);
  runCompiled<void, TerrainLaneArgs, terrainNoiseKernel<Wide>>(args);
}

void terrainPoint(const TerrainLaneArgs& args) noexcept {
  terrainKernel<Single>(args);
}

void nearestSegmentLanes(const SegmentLaneArgs& args) noexcept {
  runCompiled<void, SegmentLaneArgs, nearestSegmentKernel<Wide>>(args);
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
