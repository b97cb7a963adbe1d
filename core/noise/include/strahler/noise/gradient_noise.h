#pragma once

#include "strahler/geometry/vec2.h"

#include <array>
#include <cstdint>

namespace strahler::noise {

/// 2D gradient (Perlin) noise with a seeded permutation and a fixed table of 16 unit
/// gradients (no trigonometry at evaluation), so values are bit-identical everywhere.
/// Output is in about [-0.7, 0.7], zero at integer lattice points, period 256.
class GradientNoise {
public:
  /// Noise whose lattice is shuffled by `seed`.
  explicit GradientNoise(std::uint64_t seed) noexcept;

  /// Noise at p (lattice units).
  double at(geometry::Vec2 p) const noexcept;

  /// Fractal sum of `octaves` octaves: Σ gain^i · at(p · lacunarity^i), normalised so the
  /// amplitudes sum to 1.
  double fbm(geometry::Vec2 p, int octaves, double lacunarity = 2.0,
             double gain = 0.5) const noexcept;

private:
  std::array<std::uint8_t, 512> perm_{};
};

} // namespace strahler::noise
