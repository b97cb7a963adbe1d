#include "strahler/vegetation/density_field.h"

#include "strahler/base/assert.h"

#include <algorithm>

namespace strahler::vegetation {

void UniformDensity::sample(std::size_t species, std::span<const geometry::Vec2> points,
                            std::span<float> out) const {
  STRAHLER_ASSERT(out.size() == points.size(), "one density per point");
  std::fill(out.begin(), out.end(), species < values_.size() ? values_[species] : 0.0f);
}

void FunctionDensity::sample(std::size_t species, std::span<const geometry::Vec2> points,
                             std::span<float> out) const {
  STRAHLER_ASSERT(out.size() == points.size(), "one density per point");
  for (std::size_t i = 0; i < points.size(); ++i)
    out[i] = fn_(species, points[i]);
}

} // namespace strahler::vegetation
