#pragma once

#include "strahler/base/result.h"

#include <functional>
#include <span>
#include <vector>

namespace strahler::erosion {

/// Where an erode() call is: `round` of `rounds` done, then `finalSweeps` of the final
/// stabilisation (whose count is only known when it ends, at most Params::maxFinalSweeps).
struct Progress {
  int round = 0;       ///< Rounds completed.
  int rounds = 0;      ///< Params::iterations.
  int finalSweeps = 0; ///< Final stabilisation sweeps completed.
};

/// The parameters of the seed's two-layer erosion (seed 004, §1.3). One round ("iteration") is
/// thermal erosion, hydraulic erosion, then `sweepsPerIteration` stabilisation sweeps; after
/// the last round the stabilisation runs until it reaches `toleranceM`. Slopes are tan β
/// (m per m) of the surface B + S, from layers::gradientAt.
struct Params {
  int iterations = 50;      ///< N rounds, 0 … kMaxIterations.
  bool thermal = true;      ///< Run the thermal step (--erode thermal).
  bool hydraulic = true;    ///< Run the hydraulic step (--erode hydraulic).
  double thermalRate = 1.0; ///< Seed's T (thermal): m of bedrock weathered per round at I·tanβ = 1.
  double hydraulicRate = 2.0; ///< Seed's T (hydraulic): m carried downhill per round at H·tanβ = 1.
  double talusDegrees = 45.0;  ///< The seed's talus angle (isStable: tan 45), in (0, 90).
  double toleranceM = 0.01;    ///< Stabilisation ends when no cell can shed more than this, m.
  int sweepsPerIteration = 4;  ///< Stabilisation sweeps in each round, ≥ 1.
  int maxFinalSweeps = 100000; ///< Cap on the final stabilisation's sweeps, ≥ 1.
  int threads = 0;             ///< Worker threads; 0 = hardware concurrency. Never changes a byte.
  /// Called after every round and final sweep when set (never changes a byte); returning
  /// false stops erode(), which then fails with kInternal "erosion: cancelled".
  std::function<bool(const Progress&)> onProgress;

  static constexpr int kMaxIterations = 10000; ///< The largest accepted `iterations`.
};

/// The eroded grid: bedrock B and sediment S (surface B + S), row-major, north row first.
struct Layers {
  int width = 0;                ///< Samples per row.
  int height = 0;               ///< Rows.
  double spacing = 0.0;         ///< Metres between neighbouring samples.
  std::vector<double> bedrock;  ///< B, m.
  std::vector<double> sediment; ///< S ≥ 0, m.
  int finalSweeps = 0;          ///< Sweeps the final stabilisation took.
  bool stable = false;          ///< True when the final stabilisation reached toleranceM.

  /// B + S per sample: the eroded heightmap.
  std::vector<double> surface() const;
};

/// Ok, or a kOutOfRange error naming the first parameter outside its range.
base::Status validate(const Params& params);

/// Erodes a `width` × `height` grid of `heights` (row-major, north row first, `spacing` m):
/// B starts as the heights, S as zero. Illumination I (layers::skyView) and humidity H (the
/// seed's flow accumulation, humidityMap) are computed once from the input, as the seed
/// computes its maps before the erosion. Material never leaves the grid (the border reflects:
/// no flow across it), so Σ(B + S) equals Σ heights within 1e-9 m per sample (rounding only;
/// weathering turns 1 m³ of bedrock into 1 m³ of sediment, the seed has no other factor).
/// Deterministic: the same bytes for any `threads` (rows split into bands, every cell written
/// by one thread from double-buffered inputs, no floating-point sums across threads).
/// Memory: about nine doubles per sample (1.2 GB at 4097²). Errors: bad parameters or sizes.
base::Result<Layers> erode(std::span<const double> heights, int width, int height, double spacing,
                           const Params& params);

/// The seed's illumination I in [0, 1] of a grid (layers::skyView, edges extended), row-major.
std::vector<double> illuminationMap(std::span<const double> heights, int width, int height,
                                    double spacing, int threads);

/// The seed's humidity H in [0, 1]: every cell starts with 1, cells are visited from the
/// highest down and pass their water to lower neighbours in proportion to the drop per metre;
/// H = ln(water) / ln(largest water) (1 everywhere when nothing flows). Row-major.
std::vector<double> humidityMap(std::span<const double> heights, int width, int height,
                                double spacing);

/// The most sediment any cell could still shed: over the cells, min(S, largest height of the
/// surface above a neighbour's talus plane). ≤ toleranceM after a complete erode().
double talusExcess(const Layers& layers, double talusDegrees);

} // namespace strahler::erosion
