#pragma once
// The seed's vegetation response curves and density D = C_S(S) · (C_I(I) + C_H(H)), in one
// place: the vegetation layer tiles draw it, and vegetation placement (dart throwing against
// D) reads it at its candidate points.

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace strahler::input {
struct Params;
} // namespace strahler::input

namespace strahler::layers {

/// A response curve C(x) ∈ [0, 1]: 0 up to `rise0`, rising linearly to 1 at `rise1`, 1 up to
/// `fall1`, falling linearly to 0 at `fall0` and 0 beyond (a trapezoid; the seed draws smooth
/// bumps of this shape). rise0 ≤ rise1 ≤ fall1 ≤ fall0.
struct ResponseCurve {
  double rise0 = 0.0; ///< Below it, 0.
  double rise1 = 0.0; ///< From it, 1.
  double fall1 = 0.0; ///< Up to it, 1.
  double fall0 = 0.0; ///< Beyond it, 0.

  /// C(x).
  double operator()(double x) const noexcept;
};

/// One species' three response curves.
struct Species {
  std::string_view name;      ///< "tree", "bush": the layer's species names.
  ResponseCurve sediment;     ///< C_S of the sediment thickness S, m.
  ResponseCurve illumination; ///< C_I of the sky view I, 0 … 1.
  ResponseCurve humidity;     ///< C_H of the humidity H, 0 … 1.
};

/// The species strahler knows, with their default curves (the seed's two: trees and bushes);
/// a world's params.json may replace them ("vegetation", speciesOf()).
/// - tree: needs soil (C_S 0 below 0.3 m, 1 from 1 m), likes open sky but stands in valleys
///   (C_I 0.55 → 0.8 … 1), and moisture (C_H 0.15 → 0.45 … 1): forests on deep soil in the
///   valleys and along rivers.
/// - bush: thin soil will do (C_S 0.05 → 0.3 m … 2 m), wants sun (C_I 0.75 → 0.9 … 1), and
///   stays off wet ground (C_H 0 → 0.1 … 0.5 → 0.9): scrub on dry slopes and crests.
inline constexpr std::array<Species, 2> kSpecies{{
    {"tree", {0.3, 1.0, 10.0, 10.0}, {0.55, 0.8, 1.0, 1.0}, {0.15, 0.45, 1.0, 1.0}},
    {"bush", {0.05, 0.3, 10.0, 10.0}, {0.75, 0.9, 1.0, 1.0}, {0.0, 0.1, 0.5, 0.9}},
}};

/// kSpecies[index] with the curves a world's params.json sets for it (Params::vegetation), if
/// any. Asserts index < kSpecies.size().
Species speciesOf(const input::Params& params, std::size_t index);

/// Index of the species named `name` in kSpecies, or −1.
int speciesIndex(std::string_view name) noexcept;

/// What a plant finds at one point.
struct Environment {
  double sedimentM = 0.0;    ///< S, m (sedimentThickness()).
  double illumination = 1.0; ///< I, 0 … 1 (skyView()).
  double humidity = 0.0;     ///< H, 0 … 1 (humidity()).
  bool water = false;        ///< Sea, lake or river surface: nothing grows.
};

/// The density of `species` at `e`, in [0, 1]: the seed's D = C_S · (C_I + C_H) halved (C_I +
/// C_H reaches 2), so that D is the acceptance probability of the seed's dart throwing; 0 on
/// water.
double vegetationDensity(const Species& species, const Environment& e) noexcept;

/// vegetationDensity() at every sample of equal-sized grids (water: non-zero where water).
std::vector<double> vegetationDensity(const Species& species, std::span<const double> sedimentM,
                                      std::span<const double> illumination,
                                      std::span<const double> humidity,
                                      std::span<const std::uint8_t> water);

} // namespace strahler::layers
