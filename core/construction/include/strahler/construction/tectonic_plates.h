#pragma once

#include "strahler/geometry/vec2.h"

#include <cstdint>
#include <vector>

namespace strahler::construction {

/// The plates a world's drawn mountains imply (seed 002, "reconstitution de plaques"): a
/// Voronoi partition of the land by the mountains, each cell moving from its centroid towards
/// its mountain, cells merged into plates while their motions agree. World builds it once, on
/// a regular grid of nodes over the world (TectonicFolds::gridCell apart), when
/// WorldData::features has mountains; see docs/architecture.md, "Vector map: tectonic folds".
struct TectonicPlates {
  /// Per mountain (in file order): its cell's unit velocity, towards the mountain from the
  /// centroid of the land nodes nearest to it; (0, 0) when the cell has no land or its
  /// centroid is the mountain.
  std::vector<geometry::Vec2> cellVelocity;
  /// Per mountain: the land area of its cell, km².
  std::vector<double> cellAreaKm2;
  /// Per mountain: its plate (an index into `velocity`), plates numbered by their first
  /// mountain.
  std::vector<std::uint32_t> plateOf;
  /// Per plate: its unit velocity (the area-weighted mean of its cells', normalised; (0, 0)
  /// when that mean vanishes).
  std::vector<geometry::Vec2> velocity;
  /// Cells merged while the dot product of their plates' velocities exceeded this.
  double mergeThreshold = 1.0;
  /// How far from a convergent boundary folds reach, m.
  double foldReach = 0.0;

  friend bool operator==(const TectonicPlates&, const TectonicPlates&) = default;
};

/// The constants of the folds (see docs/architecture.md, "Vector map: tectonic folds").
struct TectonicFolds {
  static constexpr int kOctaves = 4;          ///< fBm octaves of the folds
  static constexpr double kLongest = 4096.0;  ///< m: the first octave's wavelength along the motion
  static constexpr double kElongation = 4.0;  ///< crests are this many times longer than wide
  static constexpr double kGain = 0.5;        ///< amplitude ratio of successive octaves
  static constexpr double kReliefShare = 0.1; ///< first octave's amplitude / mountains' height
  static constexpr double kMinAmplitude = 50.0;  ///< m, bounds of the first octave's amplitude
  static constexpr double kMaxAmplitude = 300.0; ///< m
  /// Each octave's slope is at most this share of the terrain blend's slope where it is added
  /// (with kNoiseSlope): folds stand out on steep ground, vanish on flats, and rarely level a
  /// slope into a pit (Corsica, 30 m cells: 99.76 % drains without burning, 99.95 % without
  /// folds; 0.5 left 99.40 % at 60 m, 1.0 99.13 %).
  static constexpr double kSlopeShare = 0.3;
  /// A bound of the lattice noise's gradient, per lattice unit (noise::LatticeNoise).
  static constexpr double kNoiseSlope = 2.0;
  /// Largest number of grid nodes (the node spacing grows to respect it).
  static constexpr std::size_t kMaxNodes = 1u << 16;
  /// Least node spacing, m.
  static constexpr double kMinNodeSpacing = 500.0;
};

} // namespace strahler::construction
