#pragma once

#include "strahler/geometry/vec2.h"

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace strahler::vegetation {

/// The density of each species over a world, the seed's D = C_S(S) · (C_I(I) + C_H(H))
/// clamped to [0, 1], asked in batches. Tiles agree at their borders only if the density is
/// a pure function of the point (never of the tile that asks), as placement asks the same
/// points from different tiles.
class DensityField {
public:
  virtual ~DensityField() = default;
  /// Writes the density in [0, 1] of kSpecies[species] at points[i] (local metres) into
  /// out[i]; out.size() == points.size(). Called once per species and tile, with every
  /// candidate of the tile and its border, so a grid-backed field can sample in one pass.
  virtual void sample(std::size_t species, std::span<const geometry::Vec2> points,
                      std::span<float> out) const = 0;
};

/// The same density everywhere, per species (tests, benchmarks, worlds without layers).
class UniformDensity final : public DensityField {
public:
  /// `values[i]` for kSpecies[i]; species past the end get 0.
  explicit UniformDensity(std::vector<float> values) : values_(std::move(values)) {}
  /// Fills out with the species' value.
  void sample(std::size_t species, std::span<const geometry::Vec2> points,
              std::span<float> out) const override;

private:
  std::vector<float> values_;
};

/// A density given point by point (tests, and fields cheap enough not to need batches).
class FunctionDensity final : public DensityField {
public:
  /// fn(species, point) in [0, 1]; it must be pure (see DensityField).
  explicit FunctionDensity(std::function<float(std::size_t, geometry::Vec2)> fn)
      : fn_(std::move(fn)) {}
  /// Calls fn for every point.
  void sample(std::size_t species, std::span<const geometry::Vec2> points,
              std::span<float> out) const override;

private:
  std::function<float(std::size_t, geometry::Vec2)> fn_;
};

} // namespace strahler::vegetation
