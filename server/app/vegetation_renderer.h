#pragma once

#include "tile_renderer.h"

#include "strahler/construction/world.h"
#include "strahler/tiling/water_mask.h"

namespace strahler::app {

/// Renders TileKind::kVegetation: the trees and bushes of a Web Mercator tile as JSON
/// (vegetation::writeVegetationJson, with each plant's local metres and ground height interpolated
/// on the lattice), placed by vegetation::placeWebTile against the
/// vegetation layer's density on the fixed lattice of LatticeDensity, so that a tile's
/// instances are those of its four children. kNotFound at zooms without vegetation (naming
/// the zooms that have it); gzipped when the request asks for it.
class VegetationRenderer final : public TileRenderer {
public:
  /// A renderer over `world` (which must outlive it), for its seed, water and rivers.
  explicit VegetationRenderer(const construction::World& world);

  /// See TileRenderer::render.
  base::Result<RenderedTile> render(const RenderContext& context, const TileRequest& request,
                                    int size) const override;

private:
  const construction::World& world_;
  tiling::WaterMask water_;
};

} // namespace strahler::app
