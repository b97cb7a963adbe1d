#include "strahler/erosion/erosion.h"

#include "grid_ops.h"

#include "strahler/layers/bordered_heights.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

namespace strahler::erosion {
namespace {

using detail::kDx;
using detail::kDy;

constexpr std::uint8_t kNoReceiver = 8;

std::size_t at(int x, int y, int width) {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
         static_cast<std::size_t>(x);
}

/// The working state: B, S, the maps and the scratch grids, all width × height.
struct State {
  int width = 0;
  int height = 0;
  double spacing = 0.0;
  int threads = 1;
  double dist[8] = {};                // Ground distance to each neighbour, m.
  std::vector<double> bedrock;        // B.
  std::vector<double> sediment;       // S.
  std::vector<double> next;           // S of the next sweep (double buffer).
  std::vector<double> moved;          // Per cell: material leaving it this step, m.
  std::vector<double> share;          // Per cell: the stabilisation's sum of excesses, m.
  std::vector<double> light;          // I.
  std::vector<double> wet;            // H.
  std::vector<double> bordered;       // The surface with a one-sample border, for gradientAt.
  std::vector<double> spacings;       // Per bordered row.
  std::vector<std::uint8_t> receiver; // The hydraulic step's downhill neighbour.

  double surface(std::size_t i) const { return bedrock[i] + sediment[i]; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
};

/// tan β of the surface B + S at every cell, through layers::gradientAt, into `out`.
void slopes(State& s, std::vector<double>& out) {
  std::vector<double> surface(s.bedrock.size());
  for (std::size_t i = 0; i < surface.size(); ++i)
    surface[i] = s.surface(i);
  detail::extendEdges(surface, s.width, s.height, 1, s.bordered);
  surface.clear();
  surface.shrink_to_fit();
  layers::BorderedHeights grid;
  grid.heights = s.bordered;
  grid.width = s.width;
  grid.height = s.height;
  grid.border = 1;
  grid.rowSpacing = s.spacings;
  out.resize(s.bedrock.size());
  detail::forBands(s.height, s.threads, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < s.width; ++x) {
        const layers::Gradient g = layers::gradientAt(grid, x, y);
        out[at(x, y, s.width)] = std::hypot(g.dzdx, g.dzdy);
      }
  });
}

/// Seed §1.3.1: B −= T·Sl·I, S += T·Sl·I, per cell.
void thermalStep(State& s, const Params& p) {
  slopes(s, s.moved);
  detail::forBands(s.height, s.threads, [&](int y0, int y1) {
    for (std::size_t i = at(0, y0, s.width); i < at(0, y1, s.width); ++i) {
      const double amount = p.thermalRate * s.moved[i] * s.light[i];
      s.bedrock[i] -= amount;
      s.sediment[i] += amount;
    }
  });
}

/// Seed §1.3.2, with the material carried rather than lost: Qa = T·H·Sl is taken from S, then
/// from B for the rest, and laid as sediment on the steepest-descent neighbour; Qa is at most
/// half the drop to it, so no step digs a pit or raises a cell above its donor.
void hydraulicStep(State& s, const Params& p) {
  slopes(s, s.moved);
  detail::forBands(s.height, s.threads, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < s.width; ++x) {
        const std::size_t i = at(x, y, s.width);
        const double h = s.surface(i);
        double best = 0.0;
        double drop = 0.0;
        std::uint8_t to = kNoReceiver;
        for (int k = 0; k < 8; ++k) {
          if (!s.inside(x + kDx[k], y + kDy[k]))
            continue;
          const double d = h - s.surface(at(x + kDx[k], y + kDy[k], s.width));
          if (d / s.dist[k] > best) {
            best = d / s.dist[k];
            drop = d;
            to = static_cast<std::uint8_t>(k);
          }
        }
        s.receiver[i] = to;
        s.moved[i] =
            to == kNoReceiver ? 0.0 : std::min(p.hydraulicRate * s.wet[i] * s.moved[i], 0.5 * drop);
      }
  });
  // Gather: each cell loses its own Qa and receives its neighbours' (fixed order).
  detail::forBands(s.height, s.threads, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < s.width; ++x) {
        const std::size_t i = at(x, y, s.width);
        const double fromSediment = std::min(s.sediment[i], s.moved[i]);
        double sediment = s.sediment[i] - fromSediment;
        s.bedrock[i] -= s.moved[i] - fromSediment;
        for (int k = 0; k < 8; ++k) {
          const int nx = x - kDx[k];
          const int ny = y - kDy[k];
          if (s.inside(nx, ny) && s.receiver[at(nx, ny, s.width)] == k)
            sediment += s.moved[at(nx, ny, s.width)];
        }
        s.sediment[i] = sediment;
      }
  });
}

/// How far cell i (at x, y) stands above neighbour k's talus plane, m (≤ 0: stable toward it).
double excess(const State& s, double tanTalus, int x, int y, int k) {
  return s.surface(at(x, y, s.width)) - s.surface(at(x + kDx[k], y + kDy[k], s.width)) -
         tanTalus * s.dist[k];
}

/// One stabilisation sweep (the seed's fall(), all cells at once): a cell with sediment sheds
/// min(S, half its largest excess) to its lower neighbours in proportion to their excesses.
/// Returns the largest min(S, excess) before the sweep.
double stabiliseSweep(State& s, double tanTalus) {
  std::vector<double> rowWorst(static_cast<std::size_t>(s.height), 0.0);
  detail::forBands(s.height, s.threads, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
      double worst = 0.0;
      for (int x = 0; x < s.width; ++x) {
        const std::size_t i = at(x, y, s.width);
        double most = 0.0;
        double sum = 0.0;
        if (s.sediment[i] > 0.0)
          for (int k = 0; k < 8; ++k)
            if (s.inside(x + kDx[k], y + kDy[k])) {
              const double e = excess(s, tanTalus, x, y, k);
              if (e > 0.0) {
                most = std::max(most, e);
                sum += e;
              }
            }
        s.moved[i] = std::min(s.sediment[i], 0.5 * most);
        s.share[i] = sum;
        worst = std::max(worst, std::min(s.sediment[i], most));
      }
      rowWorst[static_cast<std::size_t>(y)] = worst;
    }
  });
  detail::forBands(s.height, s.threads, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < s.width; ++x) {
        const std::size_t i = at(x, y, s.width);
        double sediment = s.sediment[i] - s.moved[i];
        for (int k = 0; k < 8; ++k) {
          const int nx = x + kDx[k];
          const int ny = y + kDy[k];
          if (!s.inside(nx, ny))
            continue;
          const std::size_t n = at(nx, ny, s.width);
          if (s.moved[n] <= 0.0)
            continue;
          // Neighbour n's excess toward this cell: direction k seen from n is the opposite.
          const double e = s.surface(n) - s.surface(i) - tanTalus * s.dist[k];
          if (e > 0.0)
            sediment += s.moved[n] * e / s.share[n];
        }
        s.next[i] = sediment;
      }
  });
  s.sediment.swap(s.next);
  double worst = 0.0;
  for (const double w : rowWorst)
    worst = std::max(worst, w);
  return worst;
}

base::Error outOfRange(const std::string& message) {
  return base::makeError(base::ErrorCode::kOutOfRange, "erosion: " + message);
}

} // namespace

std::vector<double> Layers::surface() const {
  std::vector<double> out(bedrock.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = bedrock[i] + sediment[i];
  return out;
}

base::Status validate(const Params& p) {
  if (p.iterations < 0 || p.iterations > Params::kMaxIterations)
    return outOfRange("iterations " + std::to_string(p.iterations) + " is outside 0 … " +
                      std::to_string(Params::kMaxIterations));
  if (!(p.talusDegrees > 0.0 && p.talusDegrees < 90.0))
    return outOfRange("talus angle " + std::to_string(p.talusDegrees) + "° is outside (0°, 90°)");
  if (!(p.thermalRate >= 0.0 && std::isfinite(p.thermalRate)))
    return outOfRange("thermal rate must be a finite number ≥ 0");
  if (!(p.hydraulicRate >= 0.0 && std::isfinite(p.hydraulicRate)))
    return outOfRange("hydraulic rate must be a finite number ≥ 0");
  if (!(p.toleranceM > 0.0 && std::isfinite(p.toleranceM)))
    return outOfRange("tolerance must be a finite number > 0 m");
  if (p.sweepsPerIteration < 1 || p.maxFinalSweeps < 1)
    return outOfRange("stabilisation sweeps must be ≥ 1");
  if (p.threads < 0)
    return outOfRange("threads must be ≥ 0");
  return base::Ok{};
}

base::Result<Layers> erode(std::span<const double> heights, int width, int height, double spacing,
                           const Params& params) {
  STRAHLER_RETURN_IF_ERROR(validate(params));
  if (width < 2 || height < 2 ||
      heights.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    return base::makeError(base::ErrorCode::kInvalidInput,
                           "erosion: the grid needs width, height ≥ 2 and width·height heights");
  if (!(spacing > 0.0 && std::isfinite(spacing)))
    return outOfRange("grid spacing must be a finite number > 0 m");

  State s;
  s.width = width;
  s.height = height;
  s.spacing = spacing;
  s.threads = detail::threadCount(params.threads, height);
  for (int k = 0; k < 8; ++k)
    s.dist[k] = k < 4 ? spacing : spacing * std::numbers::sqrt2;
  s.bedrock.assign(heights.begin(), heights.end());
  s.sediment.assign(heights.size(), 0.0);
  s.next.resize(heights.size());
  s.moved.resize(heights.size());
  s.share.resize(heights.size());
  s.receiver.resize(heights.size());
  s.spacings.assign(static_cast<std::size_t>(height + 2), spacing);
  if (params.thermal)
    s.light = illuminationMap(heights, width, height, spacing, s.threads);
  if (params.hydraulic)
    s.wet = humidityMap(heights, width, height, spacing);

  const double tanTalus = std::tan(params.talusDegrees * std::numbers::pi / 180.0);
  Progress progress{0, params.iterations, 0};
  const auto report = [&] { return !params.onProgress || params.onProgress(progress); };
  for (int round = 0; round < params.iterations; ++round) {
    if (params.thermal)
      thermalStep(s, params);
    if (params.hydraulic)
      hydraulicStep(s, params);
    for (int sweep = 0; sweep < params.sweepsPerIteration; ++sweep)
      stabiliseSweep(s, tanTalus);
    progress.round = round + 1;
    if (!report())
      return base::makeError(base::ErrorCode::kInternal, "erosion: cancelled");
  }
  Layers out;
  while (out.finalSweeps < params.maxFinalSweeps) {
    ++out.finalSweeps;
    const bool stable = stabiliseSweep(s, tanTalus) <= params.toleranceM;
    progress.finalSweeps = out.finalSweeps;
    if (!report())
      return base::makeError(base::ErrorCode::kInternal, "erosion: cancelled");
    if (stable) {
      out.stable = true;
      break;
    }
  }
  out.width = width;
  out.height = height;
  out.spacing = spacing;
  out.bedrock = std::move(s.bedrock);
  out.sediment = std::move(s.sediment);
  return out;
}

double talusExcess(const Layers& layers, double talusDegrees) {
  const double tanTalus = std::tan(talusDegrees * std::numbers::pi / 180.0);
  const double dist[2] = {layers.spacing, layers.spacing * std::numbers::sqrt2};
  double worst = 0.0;
  for (int y = 0; y < layers.height; ++y)
    for (int x = 0; x < layers.width; ++x) {
      const std::size_t i = at(x, y, layers.width);
      const double h = layers.bedrock[i] + layers.sediment[i];
      double most = 0.0;
      for (int k = 0; k < 8; ++k) {
        const int nx = x + kDx[k];
        const int ny = y + kDy[k];
        if (nx < 0 || ny < 0 || nx >= layers.width || ny >= layers.height)
          continue;
        const std::size_t n = at(nx, ny, layers.width);
        most = std::max(most, h - layers.bedrock[n] - layers.sediment[n] - tanTalus * dist[k / 4]);
      }
      worst = std::max(worst, std::min(layers.sediment[i], most));
    }
  return worst;
}

} // namespace strahler::erosion
