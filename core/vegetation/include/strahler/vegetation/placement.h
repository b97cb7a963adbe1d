#pragma once

#include "strahler/geometry/aabb.h"
#include "strahler/vegetation/density_field.h"
#include "strahler/vegetation/species.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace strahler::vegetation {

/// Which points a tile owns: a box in local metres holding them all, and the exact test.
/// Tiles of one pyramid must partition the plane (each point owned by exactly one tile).
struct Footprint {
  geometry::Aabb bounds;                        ///< Holds every owned point.
  std::function<bool(geometry::Vec2)> contains; ///< True for the points the tile owns.

  /// The half-open box [min.x, max.x) × [min.y, max.y) (local tiles, tests).
  static Footprint box(const geometry::Aabb& bounds);
};

/// The rule counts, the only knobs of placement; the border a tile consults grows with them.
struct PlacementRules {
  /// Dart-throwing rounds. Round t accepts every undecided candidate that has the highest
  /// priority among the undecided candidates of its species closer than the spacing, then
  /// drops the undecided candidates closer than the spacing to one accepted in round t. With
  /// enough rounds this is exactly sequential dart throwing in priority order; the candidates
  /// still undecided after the last round are dropped.
  int dartRounds = 4;
  /// Growth steps of the seed's simulation run on the placed individuals (0 = seedlings as
  /// placed). Step t: every plant ages by one and takes radiusAt(age); plants older than
  /// maxAge die; then, all at once, a plant dies if a plant alive at the start of the
  /// competition with a strictly larger radius lies strictly closer than that radius.
  int growthSteps = 4;
};

/// Candidates placed per spacing × spacing cell of a species' world-metric grid.
inline constexpr int kCandidatesPerCell = 3;
/// Individuals per spacing² placed at density 1 by the default rules before growth, measured
/// over 400 m squares (0.529 trees, 0.528 bushes); 4 rounds place 26,423 individuals of both
/// species there where 16 place 26,426, 1 round 0.33, 2 rounds 0.49,
/// 3 rounds 0.526 per spacing². For comparison:
/// random sequential packing with unlimited candidates jams at 0.70, hexagonal packing 1.15.
inline constexpr double kPackingAtFullDensity = 0.53;
/// Tolerance of kPackingAtFullDensity over a 400 m square (tests).
inline constexpr double kPackingTolerance = 0.02;

/// Distance, m, from a tile beyond which no candidate of `species` can change a decision
/// about an individual of the tile, under `rules` for the species of `mask`: growthSteps ·
/// (largest maxRadius of mask) for the competition (a plant's fate after step t depends on
/// the plants closer than the largest radius after step t − 1), plus 2 · dartRounds ·
/// spacing for that species' dart throwing (each round looks one spacing further for the
/// acceptance and one more for the drop). A worst-case bound: chains that long are rare.
double dependencyBorder(const PlacementRules& rules, SpeciesMask mask,
                        SpeciesIndex species) noexcept;

/// One placed plant, as served.
struct Instance {
  geometry::Vec2 position;  ///< Local metres (the world's projection frame).
  SpeciesIndex species = 0; ///< Index in kSpecies.
  float radius = 0.0f;      ///< Canopy radius after growth, m.
  float rotation = 0.0f;    ///< Rendering yaw in [0, 2π] (float rounding), radians, hashed.
  float scale = 1.0f;       ///< Rendering size factor in [0.8, 1.2), from the hash.
  std::uint64_t id = 0;     ///< The candidate's hash: stable across tiles and zooms.

  /// Equal in every field, bit for bit.
  friend bool operator==(const Instance&, const Instance&) = default;
};

/// The canonical order of instances (species, then y, x, then id), in which tiles list them.
bool instanceLess(const Instance& a, const Instance& b) noexcept;

/// The instances of the species in `mask` owned by `footprint`, in canonical order: a pure
/// function of (seed, position, density, rules), so that neighbouring tiles agree at their
/// borders and any union of tiles equals the tile covering it. Candidates come from a hash of
/// (seed, species, integer cell of the species' spacing grid in local metres, k <
/// kCandidatesPerCell): each lands at a hashed point of its cell and stands when a hashed
/// u in [0, 1) is below the density there; its priority is its hash.
std::vector<Instance> placeInstances(std::uint64_t seed, const Footprint& footprint,
                                     const DensityField& density, SpeciesMask mask,
                                     const PlacementRules& rules = {});

/// A plant in the growth simulation.
struct Plant {
  geometry::Vec2 position;  ///< Local metres.
  SpeciesIndex species = 0; ///< Index in kSpecies.
  int age = 0;              ///< Steps lived; the radius is kSpecies[species].radiusAt(age).
  bool alive = true;        ///< False once dead of old age or killed by a larger plant.
};

/// Runs `steps` steps of growth, old age and competition (PlacementRules::growthSteps) on
/// `plants`, in place; the result does not depend on the plants' order.
void simulateGrowth(std::vector<Plant>& plants, int steps);

} // namespace strahler::vegetation
