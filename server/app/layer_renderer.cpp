#include "layer_renderer.h"

#include "render_clock.h"

#include "strahler/encoding/grey_png.h"
#include "strahler/layers/density_raster.h"
#include "strahler/layers/humidity.h"
#include "strahler/layers/sediment.h"
#include "strahler/layers/sky_view.h"
#include "strahler/layers/slope.h"
#include "strahler/layers/vegetation_density.h"
#include "strahler/render/shaded_relief.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace strahler::app {
namespace {

/// The step of the sky view and the rivers' wetness for a tile of `size`: 2 (a quarter of the
/// work, interpolated) where the tiles' pixel (0, 0) has even global indices, which an even
/// size guarantees.
int skyStep(int size) noexcept {
  return size % 2 == 0 ? 2 : 1;
}

/// The samples a layer needs beyond the tile on each side.
int borderOf(LayerName name, int size) noexcept {
  return name == LayerName::kIllumination || name == LayerName::kVegetation
             ? layers::SkyView::kReach + skyStep(size) - 1
             : 1;
}

/// round(v · scale) clamped to 0 … 255.
std::uint8_t byteOf(double v, double scale) noexcept {
  return static_cast<std::uint8_t>(std::clamp(std::lround(v * scale), 0l, 255l));
}

/// 8-bit grey of `values` (each · scale).
base::Result<std::string> grey8(const std::vector<double>& values, double scale, int size) {
  std::vector<std::uint8_t> bytes(values.size());
  std::transform(values.begin(), values.end(), bytes.begin(),
                 [scale](double v) { return byteOf(v, scale); });
  return encoding::encodeGrey8Png(bytes, size, size);
}

/// 16-bit grey of `values` in hundredths (of a degree), `flat` where the value is < 0; with
/// `wrap`, 36000 (a bearing rounded up to 360°) is 0.
base::Result<std::string> grey16Hundredths(const std::vector<double>& values, int size,
                                           std::uint16_t flat, bool wrap) {
  std::vector<std::uint16_t> samples(values.size());
  std::transform(values.begin(), values.end(), samples.begin(), [flat, wrap](double v) {
    if (v < 0.0)
      return flat;
    const long hundredths = std::clamp(std::lround(v * 100.0), 0l, 65534l);
    return static_cast<std::uint16_t>(wrap ? hundredths % 36000 : hundredths);
  });
  return encoding::encodeGrey16Png(samples, size, size);
}

/// The bordered grid's water mask (0 / WaterMask::kWater), restricted to the pixels inside.
std::vector<std::uint8_t> insideOf(const std::vector<std::uint8_t>& bordered, int size,
                                   int border) {
  const auto stride = static_cast<std::size_t>(size + 2 * border);
  std::vector<std::uint8_t> out;
  out.reserve(static_cast<std::size_t>(size) * static_cast<std::size_t>(size));
  for (int y = 0; y < size; ++y) {
    const auto row = bordered.begin() +
                     static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y + border) * stride +
                                                 static_cast<std::size_t>(border));
    out.insert(out.end(), row, row + size);
  }
  return out;
}

/// The vegetation layer's densities of `species`, row-major size · size.
std::vector<double> vegetationOf(const construction::World& world, const tiling::WaterMask& water,
                                 const tiling::SampleGrid& grid, const layers::BorderedHeights& h,
                                 const layers::Species& species) {
  const int size = h.width, border = h.border;
  if (size % 2 == 0) // the costly sky view and wetness at the even pixels, interpolated
    return layers::vegetationDensityRaster(species, h,
                                           layers::riverWetnessEven(world, grid, border),
                                           water.ofGrid(layers::samplesInside(grid, border, 1)));
  return layers::vegetationDensity(
      species, layers::sedimentThickness(h), layers::skyView(h, 1),
      layers::humidity(h, layers::riverWetness(world, grid, border, 1)),
      insideOf(water.ofGrid(grid), size, border));
}

} // namespace

LayerRenderer::LayerRenderer(const construction::World& world)
    : world_(world), water_(world, geometry::LocalProjection(world.data().projectionCenter.x,
                                                             world.data().projectionCenter.y)) {}

base::Result<RenderedTile> LayerRenderer::render(const RenderContext& context,
                                                 const TileRequest& request, int size) const {
  if (request.scheme == tiling::SchemeKind::kGeographic)
    return base::makeError(base::ErrorCode::kInvalidInput,
                           "layer tiles are served in the Web Mercator and local pyramids");
  const LayerOptions& layer = request.options.layer;
  RenderedTile out;
  if (layer.name == LayerName::kWater) { // no heights: the coast and rivers at the pixels
    const auto start = RenderClock::now();
    STRAHLER_ASSIGN_OR_RETURN(
        out.bytes, encoding::encodeGrey8Png(
                       water_.ofGrid(context.scheme.rasterGrid(request.tile, size)), size, size));
    out.mimeType = "image/png";
    out.encodeMs = millisecondsSince(start);
    return out;
  }
  const int border = borderOf(layer.name, size);
  const tiling::SampleGrid grid = context.scheme.borderedRasterGrid(request.tile, size, border);
  const std::vector<double> heights = evaluateGrid(context, grid, out);
  const auto start = RenderClock::now();
  const layers::BorderedHeights h{heights, size, size, border, grid.rowSpacing};
  base::Result<std::string> bytes = std::string();
  switch (layer.name) {
  case LayerName::kSlope:
    bytes = grey16Hundredths(layers::slopeDegrees(h), size, 0, false);
    break;
  case LayerName::kAspect:
    bytes = grey16Hundredths(layers::aspectDegrees(h), size, 65535, true);
    break;
  case LayerName::kIllumination:
    bytes = grey8(layers::skyView(h, skyStep(size)), 255.0, size);
    break;
  case LayerName::kHillshade: {
    std::vector<double> shade;
    shade.reserve(static_cast<std::size_t>(size) * static_cast<std::size_t>(size));
    const render::Sun sun{layer.azimuthDeg, layer.altitudeDeg};
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const layers::Gradient g = layers::gradientAt(h, x, y);
        shade.push_back(render::sunIllumination(g.dzdx, g.dzdy, sun));
      }
    bytes = grey8(shade, 255.0, size);
    break;
  }
  case LayerName::kHumidity:
    bytes = grey8(layers::humidity(h, layers::riverWetness(world_, grid, border, skyStep(size))),
                  255.0, size);
    break;
  case LayerName::kSediment:
    bytes = grey8(layers::sedimentThickness(h), 100.0, size); // centimetres
    break;
  case LayerName::kVegetation:
    bytes = grey8(vegetationOf(world_, water_, grid, h,
                               layers::speciesOf(world_.data().params,
                                                 static_cast<std::size_t>(layer.species))),
                  255.0, size);
    break;
  case LayerName::kWater: // answered above
    break;
  }
  if (!bytes)
    return bytes.error();
  out.bytes = std::move(bytes).value();
  out.mimeType = "image/png";
  out.encodeMs = millisecondsSince(start);
  return out;
}

} // namespace strahler::app
