#include "strahler/construction/operators.h"

#include <algorithm>

namespace strahler::construction {

Sample blend(Sample a, Sample b) noexcept {
  const double w = a.w + b.w;
  if (w <= 0.0)
    return {};
  return {(a.h * a.w + b.h * b.w) / w, 0.5 * w};
}

Sample blendSums(double weightedHeight, double weight, int count) noexcept {
  if (weight <= 0.0 || count <= 0)
    return {};
  return {weightedHeight / weight, weight / count};
}

Sample unite(Sample a, Sample b) noexcept {
  return {std::max(a.h, b.h), std::max(a.w, b.w)};
}

} // namespace strahler::construction
