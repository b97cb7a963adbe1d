#pragma once

#include "strahler/encoding/mesh.h"

#include <cmath>

namespace strahler::encoding::test_support {

/// A terrain-like height field in metres over local metres: broad hills, ridges, a valley
/// and fine detail, so Draco sees realistic, non-planar data.
inline float syntheticHeight(double x, double y) {
  const double hills = 420.0 + 310.0 * std::sin(x / 2300.0) * std::cos(y / 1700.0);
  const double ridges = 160.0 * std::fabs(std::sin((x + 0.6 * y) / 900.0));
  const double across = (y - 0.3 * x - 1000.0) / 600.0;
  const double valley = -260.0 * std::exp(-across * across);
  const double detail = 11.0 * std::sin(x / 97.0 + 0.3) * std::sin(y / 83.0 - 1.1);
  return static_cast<float>(hills + ridges + valley + detail);
}

/// The bordered grid input of the tile with south-west corner `origin`, sampled from
/// syntheticHeight.
inline MeshGridInput syntheticTile(int quads, double spacing, geometry::Vec2 origin,
                                   double skirtDepth, bool textureCoordinates) {
  MeshGridInput input;
  input.quads = quads;
  input.origin = origin;
  input.spacing = spacing;
  input.skirtDepth = skirtDepth;
  input.textureCoordinates = textureCoordinates;
  for (int j = -1; j <= quads + 1; ++j)
    for (int i = -1; i <= quads + 1; ++i)
      input.heights.push_back(syntheticHeight(origin.x + i * spacing, origin.y + j * spacing));
  return input;
}

} // namespace strahler::encoding::test_support
