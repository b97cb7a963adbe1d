#pragma once

#include "tile_renderer.h"

#include "strahler/construction/world.h"
#include "strahler/tiling/water_mask.h"
#include "strahler/vegetation/density_field.h"
#include "strahler/vegetation/web_tile.h"

#include <array>
#include <cstdint>
#include <vector>

namespace strahler::app {

/// The vegetation layer's density (core/layers: D per species from sediment, sky view,
/// humidity and water) as a vegetation::DensityField that is a pure function of the point:
/// computed on a fixed global lattice, the pixel centres of Web Mercator zoom kLatticeZoom
/// tiles of kLatticeSize pixels, whatever tile asks, and interpolated bilinearly between
/// lattice points. One field covers one Web Mercator tile (zoom ≥ kLatticeZoom) and the border
/// its placement consults; asking for a point outside that is a programming error. The
/// density is 0 in a lattice cell with water at a corner.
class LatticeDensity final : public vegetation::DensityField {
public:
  /// Zoom of the lattice's tiles.
  static constexpr int kLatticeZoom = 16;
  /// Pixels per side of a lattice tile (~2.4 m between lattice points at the equator).
  static constexpr int kLatticeSize = 256;

  /// The lattice block around `tile` (kLatticeZoom ≤ z ≤ kLatticeZoom + 8) with the border
  /// of every species visibleSpecies(z) places, its heights from `context` (a Web Mercator
  /// scheme), the world's rivers and `water`. `out` receives the evaluation's cost.
  LatticeDensity(const RenderContext& context, const construction::World& world,
                 const tiling::WaterMask& water, const geometry::TileId& tile, RenderedTile& out);

  /// See DensityField::sample (placement species mapped to layer species by name).
  void sample(std::size_t species, std::span<const geometry::Vec2> points,
              std::span<float> out) const override;

  /// The ground height at `point` (local metres), bilinear between lattice points, m.
  double heightAt(geometry::Vec2 point) const;

  /// Lattice points per side of the block (the tile's lattice pixels and both borders).
  int side() const noexcept { return side_; }

private:
  /// A lattice cell of the block: its north-west point's index and the point's weights.
  struct Cell {
    std::size_t index = 0; ///< Row-major index of the cell's north-west lattice point.
    double tx = 0.0;       ///< East weight in [0, 1).
    double ty = 0.0;       ///< South weight in [0, 1).
  };
  /// The cell holding `point` (local metres); asserts that it lies inside the block.
  Cell cellOf(geometry::Vec2 point) const;
  /// Bilinear interpolation of `values` (side² row-major) in `cell`.
  double interpolate(const std::vector<double>& values, const Cell& cell) const;

  geometry::LocalProjection projection_;
  std::int64_t originX_ = 0;        ///< Global lattice column of the block's first point.
  std::int64_t originY_ = 0;        ///< Global lattice row of the block's first point.
  int side_ = 0;                    ///< Lattice points per side of the block.
  std::vector<double> heights_;     ///< Ground heights, m, side² row-major.
  std::vector<std::uint8_t> water_; ///< Non-zero on water (WaterMask), side² row-major.
  /// The layer's density per placement species, side² row-major.
  std::array<std::vector<double>, vegetation::kSpecies.size()> density_;
};

} // namespace strahler::app
