#pragma once
// Colour relief: the one hypsometric tint and hillshade of strahler's pictures (the overview of
// `strahler render` and the `relief` tiles), so that a colour means the same height everywhere.

#include "strahler/image/image.h"
#include "strahler/render/canvas.h"

#include <span>

namespace strahler::render {

/// The fixed colour of a height in metres. Land (h ≥ 0) runs through the stops 0 m green
/// (92,140,78), 150 m (132,166,92), 400 m (196,186,122), 800 m brown (160,122,86), 1400 m grey
/// (140,130,124) and 2200 m white (240,240,240), linearly between stops and white above. Water
/// (h < 0: the sea and land below sea level) is blue, darkening linearly from (70,130,190) at
/// 0 m to (30,60,120) at 120 m deep and below.
Colour hypsometricTint(double heightM);

/// Lambertian hillshade factor of ground with slope (`dzdx` east, `dzdy` north, m per m), lit
/// by a sun at azimuth 315° (north-west) and altitude 45°, relief exaggerated 2×: 0.75 on flat
/// ground, up to 0.75·√2 ≈ 1.06 facing the sun, down to 0 facing away from it.
double hillshade(double dzdx, double dzdy);

/// A sun for sunIllumination(): where it stands, degrees.
struct Sun {
  double azimuthDeg = 315.0; ///< Clockwise from north, 0 … 360.
  double altitudeDeg = 45.0; ///< Above the horizon, 0 … 90.
};

/// Lambertian illumination of ground with slope (`dzdx` east, `dzdy` north, m per m) by `sun`,
/// relief exaggerated 2× as in hillshade() (the same Lambertian term): cos of the angle between
/// the ground's normal and the sun, clamped to 0 … 1 (sin(altitude) on flat ground).
double sunIllumination(double dzdx, double dzdy, const Sun& sun);

/// One pixel: the tint of `heightM` times `shade` (hillshade()) on land, clamped to 0..255; the
/// water tint unshaded below 0 m.
Colour reliefColour(double heightM, double shade);

/// The colour relief of a `width` × `height` raster from heights sampled on the same raster
/// with a one-pixel border: `bordered` holds (width + 2) · (height + 2) heights, row-major, row
/// 0 north, column 0 west; pixel (x, y) is bordered sample (x + 1, y + 1). `rowSpacing` holds
/// the ground distance between neighbouring samples of each bordered row, m (height + 2
/// values). The slope at a pixel is the central difference of its four neighbours, so a raster
/// cut out of a larger one (tiles with their neighbours' edge samples as border) gives the
/// larger one's pixels exactly. Asserts the sizes.
image::RgbImage shadeRelief(std::span<const double> bordered, int width, int height,
                            std::span<const double> rowSpacing);

} // namespace strahler::render
