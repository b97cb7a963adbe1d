#include "strahler/render/shaded_relief.h"

#include "strahler/base/assert.h"
#include "strahler/geometry/vec2.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <numbers>

namespace strahler::render {
namespace {

struct Stop {
  double h;
  Colour c;
};

constexpr Stop kLand[] = {{0, {92, 140, 78}},    {150, {132, 166, 92}},   {400, {196, 186, 122}},
                          {800, {160, 122, 86}}, {1400, {140, 130, 124}}, {2200, {240, 240, 240}}};

} // namespace

Colour hypsometricTint(double h) {
  if (h < 0.0) {
    const double t = std::clamp(-h / 120.0, 0.0, 1.0);
    return {static_cast<std::uint8_t>(70 - 40 * t), static_cast<std::uint8_t>(130 - 70 * t),
            static_cast<std::uint8_t>(190 - 70 * t)};
  }
  for (std::size_t i = 1; i < std::size(kLand); ++i)
    if (h <= kLand[i].h) {
      const double t = (h - kLand[i - 1].h) / (kLand[i].h - kLand[i - 1].h);
      Colour c;
      for (std::size_t k = 0; k < 3; ++k)
        c[k] =
            static_cast<std::uint8_t>(kLand[i - 1].c[k] + t * (kLand[i].c[k] - kLand[i - 1].c[k]));
      return c;
    }
  return std::end(kLand)[-1].c;
}

namespace {

/// The relief's vertical exaggeration in every hillshade.
constexpr double kExaggeration = 2.0;

/// n · (light.x, light.y, rise) / |n|, n the normal of the exaggerated ground: the one
/// Lambertian term of both hillshades.
double lambert(double dzdx, double dzdy, geometry::Vec2 light, double rise) {
  const double nx = -dzdx * kExaggeration, ny = -dzdy * kExaggeration;
  return (nx * light.x + ny * light.y + rise) / std::sqrt(nx * nx + ny * ny + 1.0);
}

} // namespace

double hillshade(double dzdx, double dzdy) {
  // The sun's horizontal direction; its vertical component equals that length (altitude 45°).
  const geometry::Vec2 light = geometry::normalize(geometry::Vec2{-1.0, 1.0});
  return std::clamp(lambert(dzdx, dzdy, light, 1.0) * 0.75, 0.0, 1.2);
}

double sunIllumination(double dzdx, double dzdy, const Sun& sun) {
  constexpr double kRadians = std::numbers::pi / 180.0;
  const double az = sun.azimuthDeg * kRadians, alt = sun.altitudeDeg * kRadians;
  const geometry::Vec2 light{std::sin(az) * std::cos(alt), std::cos(az) * std::cos(alt)};
  return std::clamp(lambert(dzdx, dzdy, light, std::sin(alt)), 0.0, 1.0);
}

Colour reliefColour(double h, double shade) {
  const Colour c = hypsometricTint(h);
  const double s = h < 0.0 ? 1.0 : shade;
  Colour out;
  for (std::size_t k = 0; k < 3; ++k)
    out[k] = static_cast<std::uint8_t>(std::clamp(c[k] * s, 0.0, 255.0));
  return out;
}

image::RgbImage shadeRelief(std::span<const double> bordered, int width, int height,
                            std::span<const double> rowSpacing) {
  STRAHLER_ASSERT(width > 0 && height > 0, "shadeRelief: empty raster");
  const auto w = static_cast<std::size_t>(width) + 2;
  STRAHLER_ASSERT(bordered.size() == w * (static_cast<std::size_t>(height) + 2),
                  "shadeRelief: bordered heights are not (width + 2) · (height + 2)");
  STRAHLER_ASSERT(rowSpacing.size() == static_cast<std::size_t>(height) + 2,
                  "shadeRelief: one spacing per bordered row");
  image::RgbImage img;
  img.width = width;
  img.height = height;
  img.pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  // Bordered sample (x + 1, y + 1) of pixel (x, y).
  auto at = [&](int x, int y) {
    return bordered[static_cast<std::size_t>(y + 1) * w + static_cast<std::size_t>(x + 1)];
  };
  for (int y = 0; y < height; ++y) {
    const double spacing = rowSpacing[static_cast<std::size_t>(y + 1)];
    for (int x = 0; x < width; ++x) {
      const double dx = (at(x + 1, y) - at(x - 1, y)) / (2 * spacing);
      const double dy = (at(x, y - 1) - at(x, y + 1)) / (2 * spacing); // y up
      const Colour c = reliefColour(at(x, y), hillshade(dx, dy));
      const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                             static_cast<std::size_t>(x)) *
                            3;
      std::copy(c.begin(), c.end(), img.pixels.begin() + static_cast<std::ptrdiff_t>(i));
    }
  }
  return img;
}

} // namespace strahler::render
