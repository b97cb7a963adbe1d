#include "relief_erosion.h"

#include "strahler/base/random.h"
#include "strahler/construction/world.h"
#include "strahler/geometry/aabb.h"
#include "strahler/landscape/evolution.h"
#include "strahler/noise/gradient_noise.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>
#include <vector>

namespace strahler::construction::detail {
namespace {

using geometry::Vec2;
using landscape::LatticeGrid;
using landscape::NodeRole;

constexpr std::uint64_t kErodibilityStream = 0x65726f6469626c65ull;
constexpr std::uint64_t kReceiverStream = 0x7265636569766572ull;
constexpr std::uint64_t kGrainStream = 0x677261696e00ull;
constexpr std::uint64_t kPerturbStream = 0x7065727475726200ull;
/// Nodes each side of a river's line that keep the tree's valley (fixed at the tree's
/// heights): the bicubic interpolation then reads only them within a node of the channel, so
/// its banks meet the floor without a moat (measured on Mallorca at 60 m, drainage of the
/// evaluated land, without grain: one node 94 %, two 96 %).
constexpr int kRiverBand = 2;
/// How strongly the roughness grows with slope (addRoughness): the uplift target's
/// perturbation, and the grain left after the erosion (times params.erosionGrain).
constexpr double kPerturbPerSlope = 2.0;
constexpr double kGrainPerSlope = 2.5;
/// Rise per metre of lattice through a filled depression (so that it drains).
constexpr double kFillGradient = 1e-3;
/// Lattice nodes of sea kept around the land, so that every coast node has sea beside it.
constexpr int kMargin = 3;

/// The greatest multiple of k not above v.
std::int32_t floorTo(std::int64_t v, std::int32_t k) {
  const std::int64_t q = v >= 0 ? v / k : -((-v + k - 1) / k);
  return static_cast<std::int32_t>(q * k);
}

/// The construction tree's heights at every lattice node within one node of a free or pinned
/// one (the others never meet the land: 0), in runs of a row, rows spread over the threads
/// (each run is a pure function of its points: the same values for any thread count).
LatticeGrid<double> treeHeights(const World& world, const ReliefResidual& lattice,
                                const LatticeGrid<NodeRole>& roles) {
  LatticeGrid<double> grid = LatticeGrid<double>::filled(lattice.columns, lattice.rows, 0.0);
  const auto needed = [&](int c, int r) {
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int cc = c + dc, rr = r + dr;
        if (cc >= 0 && rr >= 0 && cc < lattice.columns && rr < lattice.rows &&
            roles.values[roles.at(cc, rr)] != NodeRole::kBaseLevel)
          return true;
      }
    return false;
  };
  const unsigned threads = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
  const auto work = [&](unsigned first) {
    std::vector<Vec2> points;
    for (int r = static_cast<int>(first); r < lattice.rows; r += static_cast<int>(threads))
      for (int c = 0; c < lattice.columns;) {
        if (!needed(c, r)) {
          ++c;
          continue;
        }
        const int begin = c;
        points.clear();
        for (; c < lattice.columns && needed(c, r); ++c)
          points.push_back(
              {(lattice.column0 + c) * lattice.spacing, (lattice.row0 + r) * lattice.spacing});
        world.heights(points, lattice.spacing,
                      std::span<double>(grid.values.data() + grid.at(begin, r), points.size()));
      }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t)
    pool.emplace_back(work, t);
  work(0);
  for (std::thread& t : pool)
    t.join();
  return grid;
}

/// Off the land: base level; within kRiverBand nodes of the line of a river of the graph:
/// pinned (keeps the tree's valley); otherwise free.
LatticeGrid<NodeRole> nodeRoles(const World& world, const ReliefResidual& lattice) {
  LatticeGrid<NodeRole> roles =
      LatticeGrid<NodeRole>::filled(lattice.columns, lattice.rows, NodeRole::kBaseLevel);
  for (int r = kMargin; r + kMargin < lattice.rows; ++r)
    for (int c = kMargin; c + kMargin < lattice.columns; ++c) {
      const Vec2 p{(lattice.column0 + c) * lattice.spacing, (lattice.row0 + r) * lattice.spacing};
      if (world.land().contains(p))
        roles.values[roles.at(c, r)] = NodeRole::kFree;
    }
  // The river lines: the node nearest each point of every curve, every quarter spacing.
  for (const primitives::RiverPrimitive& river : world.data().rivers)
    for (std::size_t k = 0; k + 1 < river.curve.size(); ++k) {
      const Vec2 a = river.curve[k].position, b = river.curve[k + 1].position;
      const double length = geometry::length(b - a);
      const int steps = 1 + static_cast<int>(length / (0.25 * lattice.spacing));
      for (int s = 0; s <= steps; ++s) {
        const Vec2 p = a + (b - a) * (static_cast<double>(s) / steps);
        const auto c =
            static_cast<std::int64_t>(std::llround(p.x / lattice.spacing)) - lattice.column0;
        const auto r =
            static_cast<std::int64_t>(std::llround(p.y / lattice.spacing)) - lattice.row0;
        if (c < 0 || r < 0 || c >= lattice.columns || r >= lattice.rows)
          continue;
        const std::size_t i = roles.at(static_cast<int>(c), static_cast<int>(r));
        if (roles.values[i] == NodeRole::kBaseLevel)
          continue;
        for (int dr = -kRiverBand; dr <= kRiverBand;
             ++dr) // the channel's own cells keep the tree's valley
          for (int dc = -kRiverBand; dc <= kRiverBand; ++dc) {
            const std::int64_t cc = c + dc, rr = r + dr;
            if (cc < 0 || rr < 0 || cc >= lattice.columns || rr >= lattice.rows)
              continue;
            NodeRole& role = roles.values[roles.at(static_cast<int>(cc), static_cast<int>(rr))];
            if (role == NodeRole::kFree)
              role = NodeRole::kPinned;
          }
      }
    }
  return roles;
}

/// Erodibility and diffusivity by place: smooth warped zones of a few km (×3 in erodibility,
/// ×4 in diffusivity, independently), and erodibility banded along a regional strike (rock
/// layers of alternating hardness) whose direction turns slowly over tens of km.
void placeFields(const ReliefResidual& lattice, std::uint64_t seed, LatticeGrid<float>& erodibility,
                 LatticeGrid<float>& diffusivity) {
  const noise::GradientNoise zones(base::mixHash(seed, kErodibilityStream));
  const noise::GradientNoise soils(base::mixHash(seed, kErodibilityStream + 1));
  const noise::GradientNoise strike(base::mixHash(seed, kErodibilityStream + 2));
  const noise::GradientNoise warp(base::mixHash(seed, kErodibilityStream + 3));
  constexpr double kZone = 1.0 / 6000.0, kStrike = 1.0 / 40000.0, kWarp = 1.0 / 2500.0;
  constexpr double kBandWavelength = 900.0; // m between hard layers
  const double log3 = std::log(3.0), log4 = std::log(4.0);
  for (int r = 0; r < lattice.rows; ++r)
    for (int c = 0; c < lattice.columns; ++c) {
      const Vec2 p{(lattice.column0 + c) * lattice.spacing, (lattice.row0 + r) * lattice.spacing};
      const Vec2 w{warp.at(p * kWarp), warp.at(p * kWarp + Vec2{17.3, 4.1})};
      const Vec2 q = p + w * 1500.0;
      const double zone = std::clamp(1.4 * zones.at(q * kZone), -0.5, 0.5);
      const double soil = std::clamp(1.4 * soils.at(q * kZone + Vec2{5.7, 9.2}), -0.5, 0.5);
      const double angle = 3.0 * strike.at(p * kStrike);
      const double across = q.x * std::cos(angle) + q.y * std::sin(angle);
      const double band = std::sin(across * (2.0 * 3.141592653589793 / kBandWavelength));
      const std::size_t i = erodibility.at(c, r);
      erodibility.values[i] = static_cast<float>(std::exp(log3 * zone) * (1.0 + 0.4 * band));
      diffusivity.values[i] = static_cast<float>(std::exp(log4 * soil));
    }
}

/// Octaves of isotropic gradient noise: wavelengths in spacings, amplitudes in metres.
struct Roughness {
  std::vector<double> wavelengths;
  std::vector<double> amplitudes;
  std::uint64_t stream = 0;
};

/// Adds `roughness` to the free nodes of `heights`, its amplitude growing with the slope
/// (none on flat ground, most on steep rocky slopes, `perSlope` times the slope, capped at
/// 2.5) and, given drainage areas, fading where much water gathers (valley floors).
void addRoughness(const ReliefResidual& lattice, std::uint64_t seed, const Roughness& roughness,
                  double perSlope, const LatticeGrid<NodeRole>& roles,
                  const LatticeGrid<float>* area, LatticeGrid<double>& heights) {
  std::vector<noise::GradientNoise> octaves;
  for (std::size_t k = 0; k < roughness.wavelengths.size(); ++k)
    octaves.emplace_back(base::mixHash(seed, roughness.stream + k));
  const LatticeGrid<double> before = heights;
  const std::vector<double>& z = before.values;
  const double s = lattice.spacing;
  for (int r = 1; r + 1 < lattice.rows; ++r)
    for (int c = 1; c + 1 < lattice.columns; ++c) {
      const std::size_t i = heights.at(c, r);
      if (roles.values[i] != NodeRole::kFree)
        continue;
      const double gx = (z[heights.at(c + 1, r)] - z[heights.at(c - 1, r)]) / (2.0 * s);
      const double gy = (z[heights.at(c, r + 1)] - z[heights.at(c, r - 1)]) / (2.0 * s);
      const double slope = std::sqrt(gx * gx + gy * gy);
      double wet = 0.0; // 0.1 km² → 0, 1 km² → 1
      if (area)
        wet = std::clamp(std::log10(std::max(1.0, static_cast<double>(area->values[i]) / 1e5)), 0.0,
                         1.0);
      const double strength = std::min(2.5, 0.4 + perSlope * slope) * (1.0 - 0.8 * wet);
      double sum = 0.0;
      for (std::size_t k = 0; k < octaves.size(); ++k) {
        const double f = 1.0 / roughness.wavelengths[k];
        sum += roughness.amplitudes[k] * 1.4 *
               octaves[k].at({(c + lattice.column0) * f + 0.37, (r + lattice.row0) * f + 0.61});
      }
      heights.values[i] += strength * sum;
    }
}

} // namespace

void erodeRelief(WorldData& data, const base::ProgressCallback& progress) {
  const input::Params& params = data.params;
  if (params.erosionSteps <= 0 || data.land.empty())
    return;
  const World world(data);
  ReliefResidual lattice;
  lattice.spacing = params.erosionCell;
  const geometry::Aabb box = world.land().bounds();
  const auto low = [&](double v) {
    return floorTo(static_cast<std::int64_t>(std::floor(v / lattice.spacing)) - kMargin,
                   ReliefResidual::kChunk);
  };
  const auto high = [&](double v) {
    return floorTo(static_cast<std::int64_t>(std::ceil(v / lattice.spacing)) + kMargin +
                       ReliefResidual::kChunk,
                   ReliefResidual::kChunk);
  };
  lattice.column0 = low(box.min.x);
  lattice.row0 = low(box.min.y);
  lattice.columns = high(box.max.x) - lattice.column0;
  lattice.rows = high(box.max.y) - lattice.row0;

  landscape::EvolutionInput input;
  input.roles = nodeRoles(world, lattice);
  input.tree = treeHeights(world, lattice, input.roles);
  const LatticeGrid<double> tree = input.tree;
  input.erodibility = LatticeGrid<float>::filled(lattice.columns, lattice.rows, 1.0f);
  input.diffusivity = LatticeGrid<float>::filled(lattice.columns, lattice.rows, 1.0f);
  placeFields(lattice, params.seed, input.erodibility, input.diffusivity);

  landscape::EvolutionParams evolution;
  evolution.spacing = lattice.spacing;
  evolution.steps = params.erosionSteps;
  evolution.incision *= params.erosionStrength;
  evolution.diffusivity *= params.hillslopeDiffusivity;
  evolution.seed = base::mixHash(params.seed, kReceiverStream);
  // The uplift's target: the tree roughened at 2–17 spacings, so that the erosion organises
  // that roughness into drainage (valleys form where it converges), as real networks grow.
  addRoughness(lattice, params.seed,
               {{2.3, 4.3, 8.7, 17.1}, {3.0, 6.0, 10.0, 16.0}, kPerturbStream}, kPerturbPerSlope,
               input.roles, nullptr, input.tree);
  landscape::EvolutionResult eroded = landscape::evolveLandscape(input, evolution, progress);
  addRoughness(lattice, params.seed, {{2.1, 4.3, 8.3}, {4.0, 6.0, 9.0}, kGrainStream},
               kGrainPerSlope * params.erosionGrain, input.roles, &eroded.area, eroded.heights);
  landscape::fillDepressions(eroded.heights, input.roles, kFillGradient * lattice.spacing);

  // The residual: eroded − tree at the free nodes (0 at the fixed ones, which keep the tree).
  lattice.quanta.assign(tree.size(), 0);
  constexpr double kLimit = std::numeric_limits<std::int16_t>::max();
  for (std::size_t i = 0; i < lattice.quanta.size(); ++i) {
    if (input.roles.values[i] != NodeRole::kFree)
      continue;
    const double units = (eroded.heights.values[i] - tree.values[i]) / ReliefResidual::kQuantum;
    lattice.quanta[i] = static_cast<std::int16_t>(std::clamp(std::round(units), -kLimit, kLimit));
  }
  data.relief = std::move(lattice);
}

} // namespace strahler::construction::detail
