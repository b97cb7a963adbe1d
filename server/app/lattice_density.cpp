#include "lattice_density.h"

#include "strahler/base/assert.h"
#include "strahler/layers/humidity.h"
#include "strahler/layers/sediment.h"
#include "strahler/layers/sky_view.h"
#include "strahler/layers/vegetation_density.h"

#include <algorithm>
#include <cmath>

namespace strahler::app {
namespace {

/// The sky view's and rivers' step: 2, as the layer tiles (every block starts on even global
/// lattice indices, so the computed points are the same global points from every tile).
constexpr int kSkyStep = 2;
/// The samples the layer maths read beyond the block (layer_renderer.cpp's border).
constexpr int kLayerBorder = layers::SkyView::kReach + kSkyStep - 1;

/// The placement border of `tile`, m: every candidate a tile's placement asks about lies
/// closer than this to the footprint (dependencyBorder, plus the spacing by which the
/// candidate grid grows the box, plus one cell a candidate may lie beyond it).
double placementReach(const geometry::TileId& tile) {
  const vegetation::SpeciesMask mask = vegetation::visibleSpecies(tile.z);
  double reach = 0.0;
  for (std::size_t s = 0; s < vegetation::kSpecies.size(); ++s)
    if (mask & (vegetation::SpeciesMask{1} << s))
      reach = std::max(
          reach, vegetation::dependencyBorder({}, mask, static_cast<vegetation::SpeciesIndex>(s)) +
                     2.0 * vegetation::kSpecies[s].spacing);
  return reach;
}

} // namespace

LatticeDensity::LatticeDensity(const RenderContext& context, const construction::World& world,
                               const tiling::WaterMask& water, const geometry::TileId& tile,
                               RenderedTile& out)
    : projection_(world.data().projectionCenter.x, world.data().projectionCenter.y) {
  STRAHLER_ASSERT(tile.z >= kLatticeZoom && tile.z <= kLatticeZoom + 7,
                  "the lattice is finer than the tile's pixels only from its zoom");
  // A zoom-z tile of kLatticeSize >> (z − kLatticeZoom) pixels has the lattice's pixel centres
  // (the same global indices · the same step, exactly), so its bordered raster grid is a block
  // of the lattice.
  const int size = kLatticeSize >> (tile.z - kLatticeZoom);
  const vegetation::Footprint footprint = vegetation::webTileFootprint(projection_, tile);
  const double metresPerPoint =
      std::min(footprint.bounds.size().x, footprint.bounds.size().y) / size;
  int pad = static_cast<int>(std::ceil(1.2 * placementReach(tile) / metresPerPoint)) + 2;
  pad += pad % 2; // even: the block's first point keeps even global indices
  const int border = pad + kLayerBorder;
  const geometry::TileId id{tile.z, tile.x, tile.y};
  const tiling::SampleGrid grid = context.scheme.borderedRasterGrid(id, size, border);
  const std::vector<double> bordered = evaluateGrid(context, grid, out);
  side_ = size + 2 * pad;
  originX_ = tile.x * size - pad;
  originY_ = tile.y * size - pad;
  const layers::BorderedHeights h{bordered, side_, side_, kLayerBorder, grid.rowSpacing};
  const std::vector<double> sediment = layers::sedimentThickness(h);
  const std::vector<double> sky = layers::skyView(h, kSkyStep);
  const std::vector<double> humidity =
      layers::humidity(h, layers::riverWetness(world, grid, kLayerBorder, kSkyStep));
  const std::vector<std::uint8_t> wet = water.ofGrid(grid);
  water_.reserve(static_cast<std::size_t>(side_) * static_cast<std::size_t>(side_));
  heights_.reserve(water_.capacity());
  for (int y = 0; y < side_; ++y)
    for (int x = 0; x < side_; ++x) {
      const auto i = static_cast<std::size_t>(y + kLayerBorder) * h.stride() +
                     static_cast<std::size_t>(x + kLayerBorder);
      water_.push_back(wet[i]);
      heights_.push_back(bordered[i]);
    }
  for (std::size_t s = 0; s < vegetation::kSpecies.size(); ++s) {
    const int layer = layers::speciesIndex(vegetation::kSpecies[s].name);
    if (layer < 0) {
      density_[s].assign(heights_.size(), 0.0);
      continue;
    }
    density_[s] = layers::vegetationDensity(
        layers::speciesOf(world.data().params, static_cast<std::size_t>(layer)), sediment, sky,
        humidity, water_);
  }
}

LatticeDensity::Cell LatticeDensity::cellOf(geometry::Vec2 point) const {
  // Global lattice coordinates: pixel coordinates of the zoom kLatticeZoom + 8 unit tile
  // (2^8 = kLatticeSize pixels per lattice tile), pixel centres at integer + 0.5. Subtracting
  // 0.5 and the block's origin is exact, so every block finds the same cell and weights.
  const geometry::Vec2 c =
      vegetation::tileCoordinates({kLatticeZoom + 8, 0, 0}, projection_.inverse(point));
  const double gx = c.x - 0.5 - static_cast<double>(originX_);
  const double gy = c.y - 0.5 - static_cast<double>(originY_);
  const double fx0 = std::floor(gx), fy0 = std::floor(gy);
  STRAHLER_ASSERT(fx0 >= 0.0 && fy0 >= 0.0 && fx0 + 1.0 < side_ && fy0 + 1.0 < side_,
                  "a vegetation density asked outside its tile's lattice block");
  const auto n = static_cast<std::size_t>(side_);
  return {static_cast<std::size_t>(fy0) * n + static_cast<std::size_t>(fx0), gx - fx0, gy - fy0};
}

double LatticeDensity::interpolate(const std::vector<double>& values, const Cell& cell) const {
  const std::size_t i = cell.index, n = static_cast<std::size_t>(side_);
  const double top = values[i] * (1.0 - cell.tx) + values[i + 1] * cell.tx;
  const double bottom = values[i + n] * (1.0 - cell.tx) + values[i + n + 1] * cell.tx;
  return top * (1.0 - cell.ty) + bottom * cell.ty;
}

void LatticeDensity::sample(std::size_t species, std::span<const geometry::Vec2> points,
                            std::span<float> out) const {
  STRAHLER_ASSERT(species < density_.size() && out.size() == points.size(),
                  "density sample: bad species or sizes");
  const auto n = static_cast<std::size_t>(side_);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Cell cell = cellOf(points[i]);
    const std::size_t k = cell.index;
    // Nothing grows in a lattice cell that touches water: no plant stands on the sea, a lake
    // or a river however the density blends across the shore.
    const bool wet = water_[k] || water_[k + 1] || water_[k + n] || water_[k + n + 1];
    out[i] = wet ? 0.0f : static_cast<float>(interpolate(density_[species], cell));
  }
}

double LatticeDensity::heightAt(geometry::Vec2 point) const {
  return interpolate(heights_, cellOf(point));
}

} // namespace strahler::app
