#include "strahler/noise/gradient_noise.h"

#include "strahler/base/random.h"

#include <utility>

namespace strahler::noise {
GradientNoise::GradientNoise(std::uint64_t seed) noexcept {
  for (int i = 0; i < 256; ++i)
    perm_[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i);
  base::Rng rng(seed, 0x6e6f697365ull);
  for (std::uint32_t i = 255; i > 0; --i) {
    const std::uint32_t j = rng.below(i + 1);
    std::swap(perm_[i], perm_[j]);
  }
  for (std::size_t i = 0; i < 256; ++i)
    perm_[i + 256] = perm_[i];
}

double GradientNoise::fbm(geometry::Vec2 p, int octaves, double lacunarity,
                          double gain) const noexcept {
  double sum = 0.0, amplitude = 1.0, norm = 0.0, frequency = 1.0;
  for (int i = 0; i < octaves; ++i) {
    // Offset each octave so lattice zeros do not line up.
    sum += amplitude * at(p * frequency + geometry::Vec2{17.31 * i, -9.73 * i});
    norm += amplitude;
    amplitude *= gain;
    frequency *= lacunarity;
  }
  return norm > 0.0 ? sum / norm : 0.0;
}

} // namespace strahler::noise
