#pragma once

namespace strahler::construction {

/// A node's value at a point: elevation h(p) and influence w(p) (Section 6).
struct Sample {
  double h = 0.0;
  double w = 0.0;
};

/// Blend B(A, B) (Section 6.2): h = (h_A w_A + h_B w_B) / (w_A + w_B), w = (w_A + w_B) / 2.
/// Where neither has influence the result is {0, 0}.
Sample blend(Sample a, Sample b) noexcept;

/// Blend of many, Σ h_i w_i / Σ w_i (DESIGN.md), given the sums Σ h_i w_i and Σ w_i and the
/// count n; w is the mean influence Σ w_i / n, which B applied pairwise gives for n = 2.
Sample blendSums(double weightedHeight, double weight, int count) noexcept;

/// Replace C(A, B): h = (1 − w_B) h_A + w_B h_B, w = w_B² + (1 − w_B) w_A. Inline: evaluation
/// applies it at every sample.
inline Sample replace(Sample a, Sample b) noexcept {
  return {(1.0 - b.w) * a.h + b.w * b.h, b.w * b.w + (1.0 - b.w) * a.w};
}

/// Union U(A, B) as the paper defines it: h = max(h_A, h_B), w = max(w_A, w_B).
Sample unite(Sample a, Sample b) noexcept;

/// Union by dominant influence: the sample with the larger w (on a tie, the lower h).
/// Inline, as replace().
inline Sample uniteByInfluence(Sample a, Sample b) noexcept {
  if (a.w != b.w)
    return a.w > b.w ? a : b;
  return a.h <= b.h ? a : b;
}

/// Union by the deeper cut into `terrain`: a sample on its river's floor (w = 1) first, then
/// the one whose replace() of the terrain is lower, i.e. the larger w·(terrain − h) (on a tie,
/// the lower h). strahler joins river primitives with it; see docs/architecture.md for why.
/// Off the floors the result of replace() is the least of every river's own, so it is
/// continuous where rivers' supports overlap. Inline, as replace().
inline Sample uniteByCut(Sample a, Sample b, double terrain) noexcept {
  const bool floorA = a.w >= 1.0, floorB = b.w >= 1.0;
  if (floorA != floorB)
    return floorA ? a : b;
  const double cutA = a.w * (terrain - a.h), cutB = b.w * (terrain - b.h);
  if (cutA != cutB)
    return cutA > cutB ? a : b;
  return a.h <= b.h ? a : b;
}

} // namespace strahler::construction
