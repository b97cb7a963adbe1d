#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace strahler::vegetation {

/// One plant species of the seed's ecosystem (004, chapter 2): its dart-throwing radius, its
/// growth and its lifespan. Lengths in metres, times in simulation steps.
struct Species {
  std::string_view name; ///< Stable lower-case name, as written in the JSON ("tree").
  double spacing;        ///< Minimum distance between two placed individuals, m (> 0).
  double startRadius;    ///< Canopy radius at age 0, m.
  double growth;         ///< Canopy radius gained per step (the seed's ε), m.
  double maxRadius;      ///< Canopy radius cap, m (≥ startRadius).
  int maxAge;            ///< Age, in steps, past which the plant dies of old age (> 0).
  int minZoom;           ///< Shallowest Web Mercator zoom at which the species is served.

  /// Canopy radius at `age` steps: startRadius + growth · age, capped at maxRadius.
  double radiusAt(int age) const noexcept;
};

/// Index of a species in kSpecies.
using SpeciesIndex = std::uint16_t;

/// The species table, tallest canopy first. The order is the canopy order: every species'
/// startRadius exceeds every later species' maxRadius, so under the seed's rule (a larger
/// plant kills a smaller one) a later species never kills an earlier one, and a tile computed
/// for trees alone holds the same trees as one computed for trees and bushes.
///
/// | species | spacing | radius      | growth/step | max age | min zoom |
/// |---------|---------|-------------|-------------|---------|----------|
/// | tree    | 4 m     | 2 → 6 m     | 0.25 m      | 40      | 16       |
/// | bush    | 2 m     | 0.4 → 1.8 m | 0.1 m       | 20      | 17       |
inline constexpr std::array<Species, 2> kSpecies{{
    {"tree", 4.0, 2.0, 0.25, 6.0, 40, 16},
    {"bush", 2.0, 0.4, 0.1, 1.8, 20, 17},
}};

/// A set of species, bit i for kSpecies[i].
using SpeciesMask = std::uint32_t;
/// Every species of kSpecies.
inline constexpr SpeciesMask kAllSpecies = (SpeciesMask{1} << kSpecies.size()) - 1;

/// Deepest Web Mercator zoom with vegetation (the deepest zoom strahler serves).
inline constexpr int kMaxVegetationZoom = 18;
/// Cap on the instances of one tile; minZoom is chosen so that instanceBound() of a tile at
/// the equator (the largest ground tile) stays below it at every served zoom.
inline constexpr std::size_t kMaxInstancesPerTile = std::size_t{1} << 16;

/// The species served at Web Mercator zoom z: those with minZoom ≤ z, for z ≤
/// kMaxVegetationZoom; empty (0) at other zooms, where individuals are not visible.
SpeciesMask visibleSpecies(int zoom) noexcept;

/// Upper bound on the individuals of `species` in a w × h m rectangle: pairwise distances are
/// ≥ spacing, so disks of radius spacing/2 are disjoint and lie in the rectangle grown by
/// spacing/2, giving n ≤ (w + s)(h + s) / (π s² / 4).
std::size_t instanceBound(const Species& species, double width, double height) noexcept;

/// instanceBound() summed over `mask` for a Web Mercator tile at zoom z, taken at the
/// equator (where tiles are largest on the ground) with 1 % margin for the local projection.
std::size_t maxInstancesPerWebTile(int zoom, SpeciesMask mask) noexcept;

} // namespace strahler::vegetation
