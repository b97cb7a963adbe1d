#pragma once

#include "strahler/construction/tectonic_plates.h"
#include "strahler/construction/world_data.h"
#include "strahler/geometry/aabb.h"
#include "strahler/geometry/polygon_index.h"
#include "strahler/noise/lattice_noise.h"

#include <cstdint>
#include <vector>

namespace strahler::construction::detail {

/// The tectonic folds of a world with drawn mountains (seed 002): its plates
/// (TectonicPlates) and, on a grid of nodes over the world, each node's plate and fold
/// strength (strongest at some distance from convergent plate boundaries, 0 on every
/// boundary and beyond the folds' reach), so that the fold at a point is a constant-time,
/// stateless function of the point: the four nodes around it, one fBm in its plate's frame
/// (evaluated by the terrain kernels: evaluation_kernels.inc, foldsKernel).
class Folds {
public:
  /// The plates and the grid for `data` (whose features have at least one mountain) over
  /// `bounds`, the land given by `land`. Deterministic: ordered, single-threaded operations.
  Folds(const WorldData& data, const geometry::PolygonIndex& land, const geometry::Aabb& bounds);

  /// The plates.
  const TectonicPlates& plates() const noexcept { return plates_; }
  /// The fold strength at p in [0, 1] (bilinear between the nodes around p).
  double strength(geometry::Vec2 p) const noexcept;
  /// What the folds' fBm reads at a point: its strength (0: no fold; the rest is then 0),
  /// its coordinates (m) along its plate's motion and across it, and its plate's lattice
  /// offset.
  struct Frame {
    double strength = 0.0;
    double along = 0.0;
    double across = 0.0;
    double offset = 0.0;
  };
  /// The frame at p: the four nodes around it (one scalar function for every evaluation path).
  Frame frame(geometry::Vec2 p) const noexcept;
  /// The first octave's amplitude, m.
  double amplitude() const noexcept { return amplitude_; }
  /// The folds' lattice noise.
  const noise::LatticeNoise& noise() const noexcept { return noise_; }

private:
  /// The grid cell holding p: its four nodes (south-west, south-east, north-west, north-east)
  /// and p's place in it.
  struct Cell {
    std::size_t corners[4];
    double tx, ty;
  };
  Cell cellAt(geometry::Vec2 p) const noexcept;
  /// The strength at the cell's point, bilinear between its nodes.
  double bilinear(const Cell& cell) const noexcept;
  geometry::Vec2 origin_;
  double spacing_ = 1.0;
  double inverseSpacing_ = 1.0;
  int nx_ = 0, ny_ = 0;               // nodes per row, rows (≥ 2 each)
  std::vector<std::uint32_t> plate_;  // per node
  std::vector<double> strength_;      // per node, in [0, 1]
  std::vector<geometry::Vec2> along_; // per plate: the unit direction of its motion
  double amplitude_ = 0.0;
  TectonicPlates plates_;
  noise::LatticeNoise noise_;
};

} // namespace strahler::construction::detail
