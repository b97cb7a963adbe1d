#include "strahler/vegetation/species.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strahler::vegetation {
namespace {

/// Equatorial circumference of the spherical Web Mercator, m (2π · 6378137).
constexpr double kWebCircumference = 2.0 * std::numbers::pi * 6378137.0;

} // namespace

double Species::radiusAt(int age) const noexcept {
  return std::min(maxRadius, startRadius + growth * static_cast<double>(age));
}

SpeciesMask visibleSpecies(int zoom) noexcept {
  if (zoom > kMaxVegetationZoom)
    return 0;
  SpeciesMask mask = 0;
  for (std::size_t i = 0; i < kSpecies.size(); ++i)
    if (zoom >= kSpecies[i].minZoom)
      mask |= SpeciesMask{1} << i;
  return mask;
}

std::size_t instanceBound(const Species& species, double width, double height) noexcept {
  const double s = species.spacing;
  const double disk = std::numbers::pi * s * s / 4.0;
  return static_cast<std::size_t>(std::floor((width + s) * (height + s) / disk));
}

std::size_t maxInstancesPerWebTile(int zoom, SpeciesMask mask) noexcept {
  const double side = 1.01 * std::ldexp(kWebCircumference, -zoom);
  std::size_t total = 0;
  for (std::size_t i = 0; i < kSpecies.size(); ++i)
    if (mask & (SpeciesMask{1} << i))
      total += instanceBound(kSpecies[i], side, side);
  return total;
}

} // namespace strahler::vegetation
