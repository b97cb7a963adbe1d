#pragma once

#include "strahler/layers/bordered_heights.h"

#include <vector>

namespace strahler::layers {

/// The seed's two-layer model T = B + S as a local function: the sediment S that the seed's
/// erosion and stabilisation leave at a point, from the point's own neighbourhood. Sediment
/// does not stay on slopes at or above the angle of repose (the seed's stability test,
/// tan 45°) and collects in hollows: S = kMax · (1 − tan β / tan kReposeDeg)₊ · C, C the
/// concavity factor clamp(0.5 + c / (2 · kConcavityScale), 0, 1), c = concavityAt().
struct Sediment {
  static constexpr double kMaxM = 2.0;            ///< The thickest sediment, m.
  static constexpr double kReposeDeg = 45.0;      ///< Angle of repose (seed: tan 45° = 1).
  static constexpr double kConcavityScale = 0.05; ///< c at which C reaches 1 (m per m).
};

/// S at a point whose slope is `tanSlope` (tan β, |gradient|) and concavity `concavity`
/// (concavityAt()), m: what sedimentThickness() computes at each pixel.
double sedimentOf(double tanSlope, double concavity) noexcept;

/// Sediment thickness of every pixel, m (0 … Sediment::kMaxM), row-major width · height.
std::vector<double> sedimentThickness(const BorderedHeights& grid);

} // namespace strahler::layers
